#include "link_errors.hpp"

#include <algorithm>
#include <regex>

#include "generate.hpp"
#include "ports.hpp"

namespace fs = std::filesystem;

namespace openswarm {

namespace {

// The thread stacks openswarm.json asks for, biggest first: "blinker 1250,
// sensor 96".
std::string stacks_by_size(const AppConfig &config, unsigned default_stack) {
    std::vector<std::pair<unsigned, std::string>> stacks;
    for (const auto &t : config.threads) stacks.push_back({t.stack ? t.stack : default_stack, t.entry});
    std::sort(stacks.rbegin(), stacks.rend());
    std::string list;
    for (const auto &[bytes, entry] : stacks)
        list += (list.empty() ? "" : ", ") + entry + " " + std::to_string(bytes);
    return list;
}

std::string ram_explanation(long over, const AppConfig &config, const fs::path &generated) {
    const PortInfo &port = port_info(config.port);
    auto values = generated_config_values(generated);
    unsigned pool = values["OS_CFG_STACK_POOL_BYTES"], data = values["OS_CFG_EVENT_DATA_BYTES"];
    std::string owners = "the thread stack pool, " + std::to_string(pool) + " bytes";
    if (!config.threads.empty())
        owners += " (openswarm.json's \"stack\": " + stacks_by_size(config, port.default_stack) +
                  ", each plus the port's per-thread overhead)";
    owners += "; the events' data pool, " + std::to_string(data) + " bytes";
    return "RAM overflow by " + std::to_string(over) + " bytes: the image needs more than the " +
           std::to_string(port.ram_bytes) + " bytes of RAM the " + port.name +
           " has. Its biggest owners: " + owners +
           "; then the kernel, the devices and the app's own variables. Lower the threads' "
           "\"stack\" in " + config.file.string() +
           " (`openswarm size`, on a build that fits, shows where RAM goes), or fewer "
           "threads; the main stack needs room on top of this";
}

std::string flash_explanation(long over, const AppConfig &config) {
    const std::string note = flash_budget_note(config);
    return "flash overflow by " + std::to_string(over) + " bytes: the image does not fit the " +
           std::to_string(flash_budget(config)) + " bytes the " + config.port + " leaves a program" +
           (note.empty() ? "" : " (" + note + ")") +
           ". Make the app smaller: `openswarm size` on a build that fits shows where flash goes";
}

}  // namespace

// avr-ld says only where .bss ends for a RAM overflow: "address 0x800b69
// of x.elf section `.bss' is not within region `data'". Data addresses
// carry 0x800000; the ATmega328P's RAM starts at 0x100 (2 KB).
constexpr long avr_ram_end = 0x800000 + 0x100 + 2048;

// Who wants a heap: on the Kilobot a call of malloc, calloc, realloc or
// free, sent to an undefined __wrap_ function (ports/kilobot/cmake/
// avr-gcc.cmake); on the e-puck2 newlib's malloc, which wants _sbrk, left
// out on purpose.
static bool wants_heap(const std::string &line) {
    static const std::regex heap("undefined reference to `(__wrap_(malloc|calloc|realloc|free)|_sbrk)'");
    return std::regex_search(line, heap);
}

void LinkOverflows::scan(const std::string &line) {
    if (wants_heap(line)) {
        heap_wanted = true;
        return;
    }
    static const std::regex overflow("region `?'?([A-Za-z_]+)'? overflowed by ([0-9]+) bytes");
    static const std::regex avr_bss("address (0x80[0-9a-fA-F]{4}) of .* is not within region `data'");
    std::smatch m;
    if (std::regex_search(line, m, avr_bss)) {
        ram_over = std::max(ram_over, std::stol(m[1], nullptr, 16) - avr_ram_end);
        return;
    }
    if (!std::regex_search(line, m, overflow)) return;
    std::string region = m[1];
    std::transform(region.begin(), region.end(), region.begin(), ::tolower);
    long bytes = std::stol(m[2]);
    if (region == "text" || region == "flash") flash_over = std::max(flash_over, bytes);
    if (region == "data" || region == "ram") ram_over = std::max(ram_over, bytes);
}

std::optional<std::string> LinkOverflows::explain(const AppConfig &config,
                                                  const fs::path &generated_config) const {
    std::string text;
    // The linker's lines above name the Kilobot app's call (not newlib's
    // on the e-puck2): the functions are named here.
    if (heap_wanted)
        text = "no heap on this robot: use static memory (the app calls malloc, calloc, realloc or "
               "free; the " + config.port + "'s RAM is the kernel's pools and the stacks, sized at build "
               "time): a static array or global instead of malloc, a pool of fixed slots if things "
               "come and go, or an event declared in " + config.file.string() + " to pass data";
    if (ram_over) text += (text.empty() ? "" : "\n") + ram_explanation(ram_over, config, generated_config);
    if (flash_over) text += (text.empty() ? "" : "\n") + flash_explanation(flash_over, config);
    if (text.empty()) return std::nullopt;
    return text;
}

}  // namespace openswarm
