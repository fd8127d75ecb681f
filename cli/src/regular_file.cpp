#include "regular_file.hpp"

#include <sys/stat.h>

namespace openswarm {

std::string not_a_regular_file(const std::filesystem::path &file) {
    struct stat st;
    if (::stat(file.c_str(), &st) != 0 || S_ISREG(st.st_mode)) return "";
    if (S_ISFIFO(st.st_mode)) return "a FIFO (named pipe), which would wait for a writer forever";
    if (S_ISDIR(st.st_mode)) return "a folder";
    if (S_ISCHR(st.st_mode)) return "a character device";
    if (S_ISBLK(st.st_mode)) return "a block device";
    if (S_ISSOCK(st.st_mode)) return "a socket";
    return "not a regular file";
}

}  // namespace openswarm
