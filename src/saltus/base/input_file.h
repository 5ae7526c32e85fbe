#pragma once
/// @file
/// Reading a file the user named, with the guards every reader shares: the name must be UTF-8
/// (it goes into result.json), the file is opened without waiting (a named pipe with no writer
/// would block for ever), must be a regular file (not /dev/zero, a pipe, a socket or a folder)
/// and no larger than the reader's limit, checked before any byte is read and again while
/// reading (a file that grows).

#include <cstddef>
#include <string>

namespace saltus {

/// The whole text of `path`, at most `max_bytes` long. Throws InputError naming the file when it
/// cannot be read or is refused by a guard above; `kind` names what the reader reads in the
/// message for a file that is not regular ("model and motion files", "BVH captures").
std::string read_input_file(const std::string& path, std::size_t max_bytes,
                            const std::string& kind);

}  // namespace saltus
