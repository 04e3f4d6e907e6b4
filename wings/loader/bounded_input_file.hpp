#pragma once
/// \file bounded_input_file.hpp
/// \brief A file a wing file names (an outline CSV, a drawing) is read only if it is a
/// regular file of at most a given size: a device such as /dev/zero, a FIFO, a folder or a
/// huge file is refused before it is read.

#include <cstddef>
#include <string>

namespace flapsim::wings {

/// \param path      the file
/// \param key       dotted key of the wing-file entry naming it (for messages)
/// \param what      how messages name it ("the outline file", "the drawing")
/// \param max_bytes the largest size read
/// \throws flapsim::InputError naming the file when it does not exist, is no regular file or
///         is larger than max_bytes
void check_bounded_input_file(const std::string& path, const std::string& key, const std::string& what,
                              std::size_t max_bytes);

}  // namespace flapsim::wings
