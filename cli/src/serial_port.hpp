// A robot's serial port (the overhead controller's FTDI cable, a Kilobot's
// debug header, the e-puck2's USB serial): opened raw, 8N1, taken for this
// program alone, with errors that say which port and what to do.
#pragma once

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace openswarm {

// Why a port could not be opened or used: the whole message, ending with
// the fix. bad_input: the port given is wrong (exit 2); else the device
// failed to take or give bytes (exit 1).
struct SerialError : std::runtime_error {
    explicit SerialError(const std::string &message, bool bad = true)
        : std::runtime_error(message), bad_input(bad) {}
    bool bad_input;
};

class SerialPort {
public:
    // Opens path at baud; throws SerialError: no such port (with the ports
    // there are), not a serial port, in use by another program, no
    // permission, a baud rate the system has no setting for.
    SerialPort(const std::string &path, unsigned baud);
    ~SerialPort();
    SerialPort(const SerialPort &) = delete;
    SerialPort &operator=(const SerialPort &) = delete;

    // Writes all of data; throws SerialError when the port takes none of
    // it for timeout_seconds (nothing drains it) or goes away.
    void write_all(const uint8_t *data, size_t size, double timeout_seconds);

    int fd() const { return fd_; }
    const std::string &path() const { return path_; }

private:
    int fd_ = -1;
    std::string path_;
};

// The serial ports a robot's USB cable shows on this machine
// (/dev/ttyUSB*, /dev/ttyACM*), sorted; for errors and --help.
std::vector<std::string> serial_ports_here();

// "ports here: /dev/ttyUSB0, /dev/ttyACM0" or that there are none, for an error.
std::string serial_ports_line();

// device, or when it is "" the only robot port plugged in; throws
// SerialError when there are none or several.
std::string serial_port_to_use(const std::string &device);

}  // namespace openswarm
