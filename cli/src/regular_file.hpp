// Files the tool reads that a user names: regular files only. open() of a
// FIFO blocks until someone writes to it (issue 30: the simulator hung).
#pragma once

#include <filesystem>
#include <string>

namespace openswarm {

// "" when file is a regular file or is not there (its reader says so);
// else what it is, for a message refusing it before it is opened: "a
// FIFO (named pipe), which would wait for a writer forever" (open()
// blocks on one), "a folder", "a character device", ...
std::string not_a_regular_file(const std::filesystem::path &file);

}  // namespace openswarm
