#include "serial_port.hpp"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <filesystem>

#include <fcntl.h>
#include <poll.h>
#include <sys/file.h>
#include <sys/ioctl.h>
#include <sys/stat.h>
#include <termios.h>
#include <unistd.h>

namespace openswarm {

namespace {

const char *const WHICH_PORT = "give the robot's serial port with --device (ls /dev/ttyUSB* /dev/ttyACM*)";

speed_t speed_of(unsigned baud) {
    switch (baud) {
    case 9600: return B9600;
    case 19200: return B19200;
    case 38400: return B38400;
    case 57600: return B57600;
    case 115200: return B115200;
    case 230400: return B230400;
    case 460800: return B460800;
    case 921600: return B921600;
    default: return B0;
    }
}

std::string open_failure(const std::string &path, int error) {
    if (error == ENOENT)
        return path + ": no such serial port (" + serial_ports_line() + "); is the cable plugged in? " +
               WHICH_PORT;
    if (error == EACCES)
        return path + ": permission denied; add yourself to the serial ports' group "
                      "(sudo usermod -aG dialout $USER), log in again, and retry";
    if (error == EBUSY) return path + " is in use by another program (a monitor, KiloGUI?): close it and retry";
    return path + ": cannot open it (" + std::strerror(error) + "); " + WHICH_PORT;
}

// Raw bytes both ways, 8N1, no flow control, no echo, no line editing:
// the overhead controller's packets carry any byte value.
void make_raw(int fd, const std::string &path, unsigned baud) {
    termios tio;
    if (::tcgetattr(fd, &tio) != 0)
        throw SerialError(path + " is not a serial port (" + std::strerror(errno) + "); " + WHICH_PORT);
    ::cfmakeraw(&tio);
    tio.c_cflag |= CLOCAL | CREAD;
    tio.c_cflag &= ~(CSTOPB | CRTSCTS);
    tio.c_cc[VMIN] = 0;
    tio.c_cc[VTIME] = 0;
    ::cfsetispeed(&tio, speed_of(baud));
    ::cfsetospeed(&tio, speed_of(baud));
    if (::tcsetattr(fd, TCSANOW, &tio) != 0)
        throw SerialError(path + ": cannot set " + std::to_string(baud) + " baud 8N1 (" + std::strerror(errno) +
                          "); " + WHICH_PORT);
}

}  // namespace

SerialPort::SerialPort(const std::string &path, unsigned baud) : path_(path) {
    if (speed_of(baud) == B0)
        throw SerialError("--baud " + std::to_string(baud) +
                          ": not a rate serial ports take here; give one of 9600, 19200, 38400, 57600, "
                          "115200, 230400, 460800, 921600");
    struct stat st;
    if (::stat(path.c_str(), &st) == 0 && !S_ISCHR(st.st_mode))
        throw SerialError(path + " is not a serial port (not a character device); " + WHICH_PORT);
    // O_NONBLOCK: a modem line's open() would wait for carrier.
    fd_ = ::open(path.c_str(), O_RDWR | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
    if (fd_ < 0) throw SerialError(open_failure(path, errno));
    // Both locks: TIOCEXCL keeps out programs that do not lock (root passes
    // it), flock the ones that do (pyserial, another openswarm).
    if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
        ::close(fd_);
        throw SerialError(open_failure(path, EBUSY));
    }
    try {
        make_raw(fd_, path, baud);
    } catch (...) {
        ::close(fd_);
        throw;
    }
    ::ioctl(fd_, TIOCEXCL);
    ::tcflush(fd_, TCIOFLUSH);
}

SerialPort::~SerialPort() {
    if (fd_ >= 0) ::close(fd_);
}

void SerialPort::write_all(const uint8_t *data, size_t size, double timeout_seconds) {
    using clock = std::chrono::steady_clock;
    auto last_progress = clock::now();
    while (size > 0) {
        ssize_t n = ::write(fd_, data, size);
        if (n > 0) {
            data += n;
            size -= (size_t)n;
            last_progress = clock::now();
            continue;
        }
        if (n < 0 && errno != EAGAIN && errno != EINTR)
            throw SerialError(path_ + ": writing failed (" + std::strerror(errno) +
                              "); was the cable pulled out? Plug it in and run the command again",
                              false);
        double waited = std::chrono::duration<double>(clock::now() - last_progress).count();
        if (waited >= timeout_seconds) {
            char seconds[32];
            std::snprintf(seconds, sizeof seconds, "%g", timeout_seconds);
            throw SerialError(path_ + " took no bytes for " + seconds +
                              " s: nothing at the other end reads them; check that it is the right port "
                              "and the device is powered, then retry",
                              false);
        }
        pollfd p{fd_, POLLOUT, 0};
        ::poll(&p, 1, 50);
    }
}

std::vector<std::string> serial_ports_here() {
    std::vector<std::string> ports;
    std::error_code error;
    for (std::filesystem::directory_iterator it("/dev", error), end; !error && it != end; it.increment(error)) {
        std::string name = it->path().filename().string();
        if (name.rfind("ttyUSB", 0) == 0 || name.rfind("ttyACM", 0) == 0) ports.push_back(it->path().string());
    }
    std::sort(ports.begin(), ports.end());
    return ports;
}

std::string serial_ports_line() {
    std::vector<std::string> ports = serial_ports_here();
    if (ports.empty()) return "this machine shows no /dev/ttyUSB* or /dev/ttyACM* now";
    std::string line = "ports here: ";
    for (size_t i = 0; i < ports.size(); i++) line += (i ? ", " : "") + ports[i];
    return line;
}

std::string serial_port_to_use(const std::string &device) {
    if (!device.empty()) return device;
    std::vector<std::string> ports = serial_ports_here();
    if (ports.size() == 1) return ports[0];
    throw SerialError("which serial port? " + serial_ports_line() +
                      "; give it with --device, e.g. --device /dev/ttyUSB0");
}

}  // namespace openswarm
