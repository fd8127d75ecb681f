// openswarm monitor: the robot's serial console on our standard output -
// a Kilobot's debug header (38400 baud, its UART's rate in kilolib), an
// e-puck2's USB or Bluetooth serial (115200) - until Ctrl-C.
#include <cerrno>
#include <csignal>
#include <cstring>

#include <poll.h>
#include <unistd.h>

#include "../app_config.hpp"
#include "../serial_port.hpp"
#include "commands.hpp"

namespace openswarm {

namespace {

struct MonitorOptions {
    std::string dir = ".";
    std::string port;   // the robot; "" = the app's
    std::string device; // "" = the only serial port there is
    unsigned baud = 0;  // 0: the robot's
};

volatile std::sig_atomic_t stop_signal = 0;
void note_stop(int signal) { stop_signal = signal; }

// The robot's console rate; 0 for a robot that has none here.
unsigned console_baud(const std::string &port) {
    if (port == "kilobot") return 38400;
    if (port == "epuck2") return 115200;
    return 0;
}

// Copies the port to standard output until a signal or the port closes.
int copy_console(SerialPort &port) {
    char buffer[4096];
    while (!stop_signal) {
        pollfd p{port.fd(), POLLIN, 0};
        if (::poll(&p, 1, 100) <= 0) continue; // a signal or nothing yet: check stop_signal
        ssize_t n = ::read(port.fd(), buffer, sizeof buffer);
        if (n > 0) {
            std::fwrite(buffer, 1, (size_t)n, stdout);
            std::fflush(stdout);
        } else if (n == 0 || (errno != EAGAIN && errno != EINTR)) {
            report(port.path() + " closed (" + (n == 0 ? std::string("end of file") : std::strerror(errno)) +
                   "): the cable was pulled out or the robot switched off; plug it in and run "
                   "`openswarm monitor` again");
            return EXIT_FAILED;
        }
    }
    return EXIT_OK;
}

int monitor(const MonitorOptions &o) {
    std::string robot = port_given_or_app(o.port, o.dir);
    unsigned baud = o.baud != 0 ? o.baud : console_baud(robot);
    if (baud == 0) {
        report(robot.empty() ? "which robot? no openswarm.json in " + o.dir +
                                   "; give --port kilobot (38400 baud) or --port epuck2 (115200), or --baud"
                             : "the " + robot + " port's robots have no serial console here; give --port "
                                                "kilobot or --port epuck2, or --baud");
        return EXIT_USAGE;
    }
    std::string device = serial_port_to_use(o.device);
    SerialPort port(device, baud);
    struct sigaction action = {};
    action.sa_handler = note_stop; // no SA_RESTART: poll returns at once
    ::sigaction(SIGINT, &action, nullptr);
    ::sigaction(SIGTERM, &action, nullptr);
    std::fprintf(stderr, "openswarm: monitoring %s at %u baud; Ctrl-C to quit\n", device.c_str(), baud);
    int code = copy_console(port);
    if (stop_signal) std::fprintf(stderr, "\nopenswarm: monitor stopped\n");
    return code;
}

}  // namespace

void add_monitor_command(CLI::App &app, const Paths &) {
    auto o = std::make_shared<MonitorOptions>();
    CLI::App *cmd = app.add_subcommand("monitor", "Show the robot's serial console (Ctrl-C to quit)");
    cmd->add_option("-C,--directory", o->dir, "the app's folder (its robot sets the baud rate)")
        ->capture_default_str();
    cmd->add_option("-p,--port", o->port, "the robot: kilobot (38400 baud) or epuck2 (115200); default: the app's");
    cmd->add_option("-d,--device", o->device,
                    "the serial port (default: the only /dev/ttyUSB* or /dev/ttyACM* there is)");
    cmd->add_option("-b,--baud", o->baud, "the rate, instead of the robot's");
    cmd->callback([o] {
        try {
            exit_code = monitor(*o);
        } catch (const SerialError &e) {
            report(e.what());
            exit_code = e.bad_input ? EXIT_USAGE : EXIT_FAILED;
        }
    });
}

}  // namespace openswarm
