#include "saltus/base/input_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <cstring>

#include "saltus/base/input_error.h"
#include "saltus/base/json_reader.h"
#include "saltus/base/text_format.h"

namespace saltus {

namespace {

std::string system_error_text(int error) {
  return std::strerror(error);
}

std::string mebibytes(std::size_t bytes) {
  return message_number(static_cast<double>(bytes) / 1048576.0);
}

}  // namespace

std::string read_input_file(const std::string& path, std::size_t max_bytes,
                            const std::string& kind) {
  if (!is_valid_utf8(path))
    throw InputError(printable(path), "",
                     "the file name is not valid UTF-8; rename the file (Saltus writes file "
                     "names into its results, which are UTF-8 JSON)");
  // O_NONBLOCK: opening a named pipe must not wait for a writer; fstat then refuses it.
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NOCTTY | O_NONBLOCK);
  if (fd < 0) {
    const int error = errno;
    throw InputError(path, "", "cannot open file for reading: " + system_error_text(error));
  }
  struct Closer {
    int fd;
    ~Closer() { ::close(fd); }
  } closer{fd};
  struct stat info {};
  if (::fstat(fd, &info) != 0) {
    const int error = errno;
    throw InputError(path, "", "cannot read the file: " + system_error_text(error));
  }
  if (S_ISDIR(info.st_mode)) throw InputError(path, "", "is a folder, not a file");
  if (!S_ISREG(info.st_mode))
    throw InputError(
        path, "",
        "is not a regular file (a device, pipe or socket); Saltus reads " + kind + " only");
  if (static_cast<std::uintmax_t>(info.st_size) > max_bytes)
    throw InputError(path, "",
                     "the file is " + mebibytes(static_cast<std::size_t>(info.st_size)) +
                         " MiB; Saltus reads files of at most " + mebibytes(max_bytes) + " MiB");
  std::string text;
  text.reserve(static_cast<std::size_t>(info.st_size));
  char buffer[65536];
  for (;;) {
    const ssize_t n = ::read(fd, buffer, sizeof buffer);
    if (n < 0) {
      if (errno == EINTR) continue;
      const int error = errno;
      throw InputError(path, "", "cannot read the file: " + system_error_text(error));
    }
    if (n == 0) break;
    text.append(buffer, static_cast<std::size_t>(n));
    if (text.size() > max_bytes)  // it grew while being read
      throw InputError(
          path, "",
          "the file is larger than " + mebibytes(max_bytes) + " MiB, the most Saltus reads");
  }
  return text;
}

}  // namespace saltus
