#include "ports.hpp"

#include <cstdio>
#include <stdexcept>

#include "suggest.hpp"

namespace openswarm {

namespace {

// kilolib starts no thread: setup() and loop(), and the overhead
// controller's activities, run on the system thread (main's stack), the
// transmitter in a handler. A classic program gets the pools of
// ports/kilobot/kilolib/include/kilolib_pools.h (the same values; the
// e2e test kilolib_cost checks they agree): the system thread alone, the
// port's events, subscriptions and devices and no more.
PortLibrary kilolib() {
    return {"kilolib", "kilolib.h", {},
            {{"max_threads", 1}, {"stack_pool", 0}, {"stack_check", 0}, {"clock_event", 0},
             {"handler_context", 0}, {"max_events", 10}, {"event_data", 33},
             {"max_subscriptions", 5}, {"max_devices", 3}},
            "kilolib.c.obj"};
}

// The analog sensors' pre-processors: the ADC count, or a table mapping it.
std::vector<ProcessorInfo> kilobot_sensor_processors() {
    return {{"raw", "", "", {}, "the ADC count 0..1023 as it is"},
            {"table", "kilobot_linear_table", "kilobot_sensor_table", {},
             "counts mapped through \"points\": [[raw, value], ...], linear between them",
             PointsParam{"points", 2, 16, 0, 1023, -32768, 32767, "kilobot_table_point", "points",
                         "count"}}};
}

}  // namespace

const std::vector<PortInfo> &ports() {
    static const std::vector<PortInfo> all = {
        // Device events: LED, motors, IR in and out (1, 2, 17 and 10 bytes:
        // kilobot_devices_init), light, voltage, temperature (an int16_t each),
        // kilolib's calls (1 byte); kilobot.h, port_arch.h, port_config.h,
        // kilolib_internal.h.
        // Flash below the bootloader (OPENSWARM_FLASH_BYTES in avr-gcc.cmake).
        // The main stack: the blinky template's worst use measured in the
        // simulator is 81 bytes (openswarm size measures an app's own).
        {"kilobot", "Kilobot: ATmega328P at 8 MHz, run in simavr", 0x7000, 2048, 10, 6 + 1 + 2 + 17 + 10 + 3 * 2 + 1,
         4, 14, 96, 16, {kilolib()}, "avr-gcc",
         "sudo apt-get install gcc-avr avr-libc binutils-avr (or run OpenSwarm's ./setup.sh)",
         "ports/kilobot/cmake/avr-gcc.cmake", "avr-size", Runner::simavr,
         "of its 32768: the Kilobot's bootloader starts at 0x7000", 128},
        // The kernel's two events (6 bytes) and the board's 16 ids
        // (PORT_EVENT_COUNT in ports/cortex_m4's port_arch.h), of which
        // epuck_devices_init registers 8 at their values' sizes (wheels 4,
        // proximity 32, six of 1: 42 bytes); the whole 1 MB of flash (an
        // app's own budget is its placement's, flash_budget: less after
        // the Aseba bootloader); RAM: SRAM1+2 (the image leaves CCM unused).
        // Two images: <app>.elf for QEMU, <app>-robot.elf for the robot.
        {"epuck2", "e-puck2: STM32F407 (Cortex-M4F at 168 MHz), run in QEMU (netduinoplus2)",
         1024 * 1024, 128 * 1024, 2 + 16, 6 + 42, 16, 48, 1024, 64, {}, "arm-none-eabi-gcc",
         "sudo apt-get install gcc-arm-none-eabi libnewlib-arm-none-eabi (or run OpenSwarm's "
         "./setup.sh)",
         "ports/cortex_m4/cmake/arm-none-eabi.cmake", "arm-none-eabi-size", Runner::qemu, "", 0, ".elf",
         "-robot.elf"},
        // The kernel's two events and the board's 8 (PORT_EVENT_COUNT in
        // ports/epuck/dspic's port_arch.h, registered at 42 bytes as on the
        // e-puck2); pools from its port_config.h; 144 KB of flash, 8 KB of
        // RAM. Built with Microchip XC16, which is not in Debian, so never
        // here; nothing runs its images (no dsPIC simulator). The size tool's
        // name is XC16's binutils' (never checked: XC16 was never installed).
        {"epuck",
         "e-puck: dsPIC30F6014A at 14.7456 MIPS; needs Microchip XC16, not in Debian: build only, "
         "no simulator",
         144 * 1024, 8 * 1024, 2 + 8, 6 + 42, 6, 20, 128, 32, {}, "xc16-gcc",
         "install Microchip XC16 from https://www.microchip.com/xc16 (it is not in Debian) and put "
         "its bin folder on PATH",
         "ports/epuck/dspic/cmake/xc16.cmake", "xc16-size", Runner::none},
        // The e-puck app on the host port, one process per robot of a world
        // (ports/epuck/host): event ids and pools as on the e-puck2.
        {"epuck_world",
         "e-puck in the world simulator: the app as a host program, one per robot (openswarm run "
         "--world, openswarm experiment)",
         0, 0, 2 + 16, 6 + 42, 16, 48, 1024, 64, {}, "cc",
         "sudo apt-get install gcc (or run OpenSwarm's ./setup.sh)", "", "size", Runner::world, "", 0,
         ""},
    };
    return all;
}

const std::vector<DeviceInfo> &devices_of(const std::string &port) {
    static const std::vector<DeviceInfo> kilobot = {
        {"motors", "kilobot_motor_pair",
         {{"calibrated", "kilobot_motor_commands", "", {},
           "motion commands become the robot's EEPROM calibration; duties pass"},
          {"spinup-limited", "kilobot_spinup_limited", "kilobot_spinup_limit",
           {{"limit_ms", "limit_ms", 1, 60000}, {"fallback", "fallback", 0, 254}},
           "as calibrated, and full power drops to fallback after limit_ms"}}},
        {"led", "kilobot_led", {{"copy", "", "", {}, "the colour byte as it is"}}},
        {"ir", "kilobot_ir",
         {{"crc", "", "", {}, "frames whose CRC checks reach KILOBOT_EVENT_IR_RX"},
          {"distance", "kilobot_ir_with_distance", "", {},
           "as crc, and the sender's distance in mm (distance_mm) from the robot's EEPROM tables"}}},
        {"light", "kilobot_light", kilobot_sensor_processors()},
        {"voltage", "kilobot_voltage", kilobot_sensor_processors()},
        {"temperature", "kilobot_temperature", kilobot_sensor_processors()},
    };
    static const std::vector<DeviceInfo> none;
    return port == "kilobot" ? kilobot : none;
}

// The linker script takes the origin (ports/epuck/epuck2/robot/
// epuck2_robot.ld, EPUCK2_FLASH_ORIGIN from OPENSWARM_EPUCK2_BOOTLOADER in
// cmake/OpenSwarmKernel.cmake) and gives the image the rest of the 1 MB.
const std::vector<FlashPlacement> &epuck2_placements() {
    static const std::vector<FlashPlacement> all = {
        {"none", 0x08000000u, 1024 * 1024, "no bootloader"},
        {"aseba", 0x08020000u, 1024 * 1024 - 128 * 1024, "after the Aseba bootloader's 128 KB"},
    };
    return all;
}

const FlashPlacement &epuck2_placement(const std::string &bootloader) {
    for (const auto &p : epuck2_placements())
        if (p.bootloader == bootloader) return p;
    throw std::out_of_range("epuck2 bootloader " + bootloader);
}

std::string hex_address(unsigned address) {
    char text[16];
    std::snprintf(text, sizeof text, "0x%08X", address);
    return text;
}

std::vector<std::string> port_names() {
    std::vector<std::string> names;
    for (const auto &p : ports()) names.push_back(p.name);
    return names;
}

bool is_port(const std::string &name) {
    for (const auto &p : ports())
        if (p.name == name) return true;
    return false;
}

const PortInfo &port_info(const std::string &name) {
    for (const auto &p : ports())
        if (p.name == name) return p;
    throw std::out_of_range(name);
}

const PortCosts *costs_for(const std::string &port) {
    static const std::vector<PortCosts> all = {
        {"kilobot", 64, /* C */ 158, /* per thread */ 12, /* per event */ 4, /* devices */ 190,
         /* ports/kilobot's port_config.h */ 448},
        // bench/qemu_bench.py; its devices not measured (0 keeps the RAM
        // check a lower bound; 192 KB leave room)
        {"epuck2", 384, /* C */ 220, /* per thread */ 20, /* per event */ 8, /* devices */ 0, 0},
    };
    for (const auto &c : all)
        if (c.port == port) return &c;
    return nullptr;
}

const PortCosts &costs_of(const std::string &port) {
    const PortCosts *costs = costs_for(port);
    if (costs == nullptr) throw std::logic_error("no RAM costs for port " + port + " in footprint.cpp: add them");
    return *costs;
}

std::string unknown_port_message(const std::string &port) {
    return "unknown port '" + port + "'; ports: " + join(port_names()) + did_you_mean(port, port_names(), '\'') +
           " (`openswarm ports` says what each is)";
}

}  // namespace openswarm
