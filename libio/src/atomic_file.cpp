#include <gearkit/io/atomic_file.hpp>

#include <gearkit/io/error.hpp>

#include <fmt/format.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace gearkit::io {

namespace fs = std::filesystem;

void write_file_atomic(const std::string& path, std::string_view content, std::string_view option) {
  auto fail = [&](const std::string& reason) {
    fail_option(option, fmt::format("cannot write '{}': {}", path, reason));
  };
  if (path.empty()) fail("expected a file name, found an empty one");
  fs::path target(path);
  std::error_code ec;
  if (fs::is_directory(target, ec)) fail("it is a directory");
  fs::path dir = target.parent_path();
  if (dir.empty()) dir = ".";
  if (!fs::is_directory(dir, ec)) fail(fmt::format("folder '{}' does not exist", dir.string()));

  // The temporary sits in the target's folder so that rename() is atomic (same file system).
  std::string tmpl = (dir / ("." + target.filename().string() + ".tmp-XXXXXX")).string();
  int fd = ::mkstemp(tmpl.data());
  if (fd < 0) fail(std::strerror(errno));
  const char* p = content.data();
  std::size_t left = content.size();
  while (left > 0) {
    ssize_t n = ::write(fd, p, left);
    if (n < 0) {
      if (errno == EINTR) continue;
      int err = errno;
      ::close(fd);
      ::unlink(tmpl.c_str());
      fail(std::strerror(err));
    }
    p += n;
    left -= static_cast<std::size_t>(n);
  }
  // Files are meant to be shared (DXF to a workshop): the usual 0644 less the umask, not
  // mkstemp's 0600.
  mode_t mask = ::umask(0);
  ::umask(mask);
  ::fchmod(fd, 0666 & ~mask);
  if (::fsync(fd) != 0 || ::close(fd) != 0) {
    int err = errno;
    ::unlink(tmpl.c_str());
    fail(std::strerror(err));
  }
  if (std::rename(tmpl.c_str(), path.c_str()) != 0) {
    int err = errno;
    ::unlink(tmpl.c_str());
    fail(std::strerror(err));
  }
}

}  // namespace gearkit::io
