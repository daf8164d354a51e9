#include <gearkit/io/output.hpp>

#include <gearkit/io/error.hpp>

#include "temporary_registry.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cerrno>
#include <climits>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <mutex>
#include <ostream>
#include <random>
#include <stdexcept>
#include <streambuf>
#include <dirent.h>
#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

namespace gearkit::io {

namespace fs = std::filesystem;

namespace {

struct InputFile {
  dev_t dev;
  ino_t ino;
  std::string path;
};

std::mutex inputs_mutex;
std::vector<InputFile> inputs;

/// The input that is the same file as `st`, or nullptr.
const InputFile* input_with_id(const struct stat& st) {
  std::lock_guard lock(inputs_mutex);
  for (const auto& in : inputs)
    if (in.dev == st.st_dev && in.ino == st.st_ino) return &in;
  return nullptr;
}

[[noreturn]] void cannot_write(std::string_view option, std::string_view path, std::string_view reason) {
  fail_option(option, fmt::format("cannot write {}: {}", quote(path), reason));
}

/// Refuses standard output when the shell opened it on a file this process reads
/// (`gearkit train m.yaml 1<>m.yaml`, or `>>`): writing the report would destroy the model.
void check_standard_output_is_no_input() {
  struct stat st{};
  if (::fstat(STDOUT_FILENO, &st) != 0 || !S_ISREG(st.st_mode)) return;
  if (const InputFile* in = input_with_id(st))
    throw InputError(fmt::format("standard output is the input file {}: refusing to write over an input (redirect "
                                 "standard output elsewhere or give --output FILE)",
                                 quote(in->path)));
}

/// Writes all of [p, p+n) to fd; on failure returns false with the errno in `err`.
bool write_all(int fd, const char* p, std::size_t n, int& err) {
  while (n > 0) {
    ssize_t w = ::write(fd, p, n);
    if (w < 0) {
      if (errno == EINTR) continue;
      err = errno;
      return false;
    }
    p += w;
    n -= static_cast<std::size_t>(w);
  }
  return true;
}

/// A stream buffer onto a file descriptor that remembers the first write error (reported at
/// commit, with its errno) instead of losing it in a stream's badbit.
class FdBuffer : public std::streambuf {
 public:
  explicit FdBuffer(int fd) : fd_(fd) { setp(buffer_, buffer_ + sizeof buffer_); }
  int error() const { return error_; }

 protected:
  int_type overflow(int_type c) override {
    if (sync() != 0) return traits_type::eof();
    if (!traits_type::eq_int_type(c, traits_type::eof())) {
      *pptr() = traits_type::to_char_type(c);
      pbump(1);
    }
    return traits_type::not_eof(c);
  }
  int sync() override {
    if (error_ == 0) write_all(fd_, pbase(), static_cast<std::size_t>(pptr() - pbase()), error_);
    setp(buffer_, buffer_ + sizeof buffer_);
    return error_ == 0 ? 0 : -1;
  }

 private:
  int fd_;
  int error_ = 0;
  char buffer_[1 << 16];
};

enum class Kind { standard_output, device, file };

/// Follows a chain of symbolic links whose last target does not exist yet (writing through
/// a dangling link creates its target, as the shell's `>` does).
fs::path follow_dangling_links(const fs::path& path, std::string_view option) {
  fs::path p = path;
  for (int hop = 0; hop < 40; ++hop) {
    struct stat st{};
    if (::lstat(p.c_str(), &st) != 0 || !S_ISLNK(st.st_mode)) return p;
    std::error_code ec;
    fs::path target = fs::read_symlink(p, ec);
    if (ec) return p;
    p = target.is_absolute() ? target : p.parent_path() / target;
  }
  cannot_write(option, path.string(), "too many levels of symbolic links");
}

/// Whether `name` is a temporary of an OutputSet whose process has ended.
bool is_stale_temporary(std::string_view name) {
  if (name.size() <= kTemporarySuffix.size() + 9 || name.front() != '.' || !name.ends_with(kTemporarySuffix))
    return false;
  name.remove_suffix(kTemporarySuffix.size());
  std::size_t dot = name.rfind('.');
  if (dot == std::string_view::npos) return false;
  std::string_view tag = name.substr(dot + 1);  // "<pid>-<6 letters>"
  std::size_t dash = tag.find('-');
  if (dash == 0 || dash == std::string_view::npos || tag.size() - dash - 1 != 6) return false;
  long pid = 0;
  for (char c : tag.substr(0, dash)) {
    if (c < '0' || c > '9' || pid > 1'000'000'000) return false;
    pid = pid * 10 + (c - '0');
  }
  return ::kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH;
}

/// Removes the temporaries a killed gearkit left in `dir` (only regular files of this user).
void remove_stale_temporaries(const fs::path& dir) {
  DIR* d = ::opendir(dir.c_str());
  if (!d) return;
  while (const struct dirent* e = ::readdir(d)) {
    if (!is_stale_temporary(e->d_name)) continue;
    struct stat st{};
    if (::fstatat(::dirfd(d), e->d_name, &st, AT_SYMLINK_NOFOLLOW) == 0 && S_ISREG(st.st_mode) &&
        st.st_uid == ::geteuid())
      ::unlinkat(::dirfd(d), e->d_name, 0);
  }
  ::closedir(d);
}

std::string random_letters(std::size_t n) {
  static thread_local std::mt19937 engine{std::random_device{}()};
  static constexpr char kLetters[] = "abcdefghijklmnopqrstuvwxyz0123456789";
  std::uniform_int_distribution<int> pick(0, 35);
  std::string s;
  for (std::size_t i = 0; i < n; ++i) s += kLetters[pick(engine)];
  return s;
}

}  // namespace

void note_input_file(const std::string& path) {
  struct stat st{};
  if (::stat(path.c_str(), &st) != 0) return;
  std::lock_guard lock(inputs_mutex);
  inputs.push_back({st.st_dev, st.st_ino, path});
}

void forget_input_files() {
  std::lock_guard lock(inputs_mutex);
  inputs.clear();
}

std::vector<std::string> input_files() {
  std::lock_guard lock(inputs_mutex);
  std::vector<std::string> paths;
  for (const auto& in : inputs)
    if (std::find(paths.begin(), paths.end(), in.path) == paths.end()) paths.push_back(in.path);
  return paths;
}

struct OutputSet::Output {
  std::string option;
  std::string path;        ///< as the user gave it
  Kind kind = Kind::file;
  fs::path target;         ///< the file or device written (symlinks resolved for files)
  bool exists = false;
  struct stat existing {};  ///< of the destination, when it exists
  fs::path temporary;
  int temporary_slot = -1;  ///< its record for the signal handler (temporary_registry.hpp)
  int fd = -1;
  bool in_place = false;   ///< copy into the existing inode instead of renaming over it
  bool streamed = false;
  bool reserved = false;   ///< reserve()d: its content comes with fill(), or it is dropped
  bool filled = false;
  std::string deferred;    ///< add()'s content for standard output and devices
  std::string svg;         ///< add()'s content when it is an SVG document (for pictures())
  std::unique_ptr<FdBuffer> buffer;
  std::unique_ptr<std::ostream> stream;

  ~Output() {
    if (fd >= 0) ::close(fd);
    if (!temporary.empty()) ::unlink(temporary.c_str());
    detail::forget_temporary(temporary_slot);
  }

  [[noreturn]] void fail(std::string_view reason) const { cannot_write(option, path, reason); }
  [[noreturn]] void fail_errno(int err) const { fail(std::strerror(err)); }

  /// Kind and target of the destination; refuses folders, sockets and block devices.
  void resolve() {
    if (path.empty()) fail("expected a file name or '-' for standard output, found an empty name");
    if (path == "-") {
      kind = Kind::standard_output;
      return;
    }
    struct stat st{};
    if (::stat(path.c_str(), &st) == 0) {
      if (S_ISDIR(st.st_mode)) fail("it is a folder");
      if (S_ISCHR(st.st_mode) || S_ISFIFO(st.st_mode)) {
        kind = Kind::device;
        target = path;
        return;
      }
      if (!S_ISREG(st.st_mode)) fail("expected a regular file, a character device or a FIFO, found another special file");
      char real[PATH_MAX];
      if (!::realpath(path.c_str(), real)) fail_errno(errno);
      target = real;
      exists = true;
      existing = st;
      return;
    }
    if (errno != ENOENT) fail_errno(errno);
    target = follow_dangling_links(path, option);
    if (target.filename().empty() || target.filename() == "." || target.filename() == "..")
      fail("expected a file name, found a folder name");
    fs::path dir = target.parent_path().empty() ? fs::path(".") : target.parent_path();
    struct stat dst{};
    if (::stat(dir.c_str(), &dst) != 0 || !S_ISDIR(dst.st_mode))
      fail(fmt::format("folder {} does not exist", quote(dir.string())));
  }

  /// Refuses an input, a read-only file and a destination another output of the set has.
  void check(const std::vector<std::unique_ptr<Output>>& others) const {
    if (kind == Kind::standard_output) check_standard_output_is_no_input();
    if (exists) {
      if (const InputFile* in = input_with_id(existing))
        fail(fmt::format("it is the input file {}; refusing to replace an input", quote(in->path)));
      if (::access(target.c_str(), W_OK) != 0) fail_errno(errno);
    }
    for (const auto& o : others) {
      if (o.get() == this || o->kind != kind || kind == Kind::device) continue;
      bool same = kind == Kind::standard_output ||
                  (exists && o->exists ? existing.st_dev == o->existing.st_dev && existing.st_ino == o->existing.st_ino
                                       : fs::absolute(target).lexically_normal() == fs::absolute(o->target).lexically_normal());
      if (same)
        fail(kind == Kind::standard_output
                 ? fmt::format("standard output already receives the output of '{}'", o->option)
                 : fmt::format("'{}' writes the same file", o->option));
    }
  }

  /// Creates the temporary next to the target, with the target's permissions and owner.
  void create_temporary() {
    fs::path dir = target.parent_path().empty() ? fs::path(".") : target.parent_path();
    remove_stale_temporaries(dir);
    std::string name = target.filename().string().substr(0, 100);
    for (int attempt = 0; fd < 0; ++attempt) {
      temporary = dir / fmt::format(".{}.{}-{}{}", name, ::getpid(), random_letters(6), kTemporarySuffix);
      // Recorded before it exists, so that no signal can come between its creation and its record.
      temporary_slot = detail::remember_temporary(temporary.c_str());
      fd = ::open(temporary.c_str(), O_RDWR | O_CREAT | O_EXCL | O_CLOEXEC, exists ? 0600 : 0666);
      if (fd < 0) {
        int err = errno;
        detail::forget_temporary(temporary_slot);
        temporary_slot = -1;
        temporary.clear();
        if (err != EEXIST || attempt > 100) fail_errno(err);
      }
    }
    if (exists) {
      // A rename would give the file a new inode: other hard links would keep the old content,
      // and a file of another owner would become ours. Those are rewritten in place instead.
      in_place = existing.st_nlink > 1;
      if ((existing.st_uid != ::geteuid() || existing.st_gid != ::getegid()) &&
          ::fchown(fd, existing.st_uid, existing.st_gid) != 0)
        in_place = true;
      ::fchmod(fd, existing.st_mode & 0777);
    }
    buffer = std::make_unique<FdBuffer>(fd);
    stream = std::make_unique<std::ostream>(buffer.get());
  }

  /// Flushes the temporary to disk; write errors surface here.
  void finish() {
    stream->flush();
    if (buffer->error() != 0) fail_errno(buffer->error());
    if (::fsync(fd) != 0) fail_errno(errno);
  }

  /// Copies the finished temporary into the existing file (keeps its inode: hard links, owner).
  void copy_in_place() {
    int out = ::open(target.c_str(), O_WRONLY | O_TRUNC | O_NOCTTY | O_CLOEXEC);
    if (out < 0) fail_errno(errno);
    int err = 0;
    char chunk[1 << 16];
    ::lseek(fd, 0, SEEK_SET);
    for (ssize_t n; err == 0 && (n = ::read(fd, chunk, sizeof chunk)) != 0;) {
      if (n < 0) {
        if (errno != EINTR) err = errno;
        continue;
      }
      write_all(out, chunk, static_cast<std::size_t>(n), err);
    }
    if (err == 0 && ::fsync(out) != 0) err = errno;
    if (::close(out) != 0 && err == 0) err = errno;
    if (err != 0) fail_errno(err);
  }

  /// Puts the finished temporary in place of the target.
  void move_into_place() {
    if (in_place) copy_in_place();
    else if (::rename(temporary.c_str(), target.c_str()) != 0) fail_errno(errno);
    else {
      temporary.clear();
      detail::forget_temporary(temporary_slot);
      temporary_slot = -1;
    }
    ::close(fd);
    fd = -1;
  }

  /// Writes the deferred content to a device (opened only now: nothing reaches it before).
  void write_device() {
    if (fd < 0) fd = ::open(target.c_str(), O_WRONLY | O_NOCTTY | O_CLOEXEC);
    if (fd < 0) fail_errno(errno);
    int err = 0;
    if (streamed) {
      stream->flush();
      err = buffer->error();
    } else {
      write_all(fd, deferred.data(), deferred.size(), err);
    }
    if (err != 0) fail_errno(err);
  }
};

OutputSet::OutputSet(std::ostream& standard_output) : standard_output_(standard_output) {}

OutputSet::~OutputSet() = default;

OutputSet::Output& OutputSet::add_output(std::string_view option, const std::string& path) {
  auto out = std::make_unique<Output>();
  out->option = option;
  out->path = path;
  out->resolve();
  out->check(outputs_);
  if (out->kind == Kind::file) out->create_temporary();
  outputs_.push_back(std::move(out));
  return *outputs_.back();
}

namespace {

// An SVG document is kept for pictures() (the HTML report shows the run's pictures inline).
void remember_picture(std::string& svg, std::string_view content) {
  if (content.substr(0, 200).find("<svg") != std::string_view::npos) svg.assign(content);
}

}  // namespace

std::optional<std::string> OutputSet::standard_output_option() const {
  for (const auto& out : outputs_)
    if (out->kind == Kind::standard_output) return out->option;
  return std::nullopt;
}

void OutputSet::add(std::string_view option, const std::string& path, std::string_view content) {
  Output& out = add_output(option, path);
  remember_picture(out.svg, content);
  if (out.kind == Kind::file) out.stream->write(content.data(), static_cast<std::streamsize>(content.size()));
  else out.deferred.assign(content);
}

std::ostream& OutputSet::stream(std::string_view option, const std::string& path) {
  Output& out = add_output(option, path);
  out.streamed = true;
  if (out.kind == Kind::standard_output) return standard_output_;
  if (out.kind == Kind::device) {
    out.fd = ::open(out.target.c_str(), O_WRONLY | O_NOCTTY | O_CLOEXEC);
    if (out.fd < 0) out.fail_errno(errno);
    out.buffer = std::make_unique<FdBuffer>(out.fd);
    out.stream = std::make_unique<std::ostream>(out.buffer.get());
  }
  return *out.stream;
}

std::vector<OutputSet::Picture> OutputSet::pictures() const {
  std::vector<Picture> out;
  for (const auto& o : outputs_)
    if (!o->svg.empty()) out.push_back({o->option, o->path, o->svg});
  return out;
}

void OutputSet::finish_temporaries() {
  for (auto& out : outputs_) {
    // An input noted after add() (a late read) is still protected, before anything is written.
    if (out->kind == Kind::standard_output) check_standard_output_is_no_input();
    if (out->kind != Kind::file) continue;
    out->finish();
    out->check(outputs_);  // an input noted after add() (a late read) is still protected
  }
}

void OutputSet::write_direct_outputs() {
  for (auto& out : outputs_) {
    if (out->kind == Kind::device) {
      out->write_device();
    } else if (out->kind == Kind::standard_output) {
      errno = 0;
      standard_output_.write(out->deferred.data(), static_cast<std::streamsize>(out->deferred.size()));
      standard_output_.flush();
      if (!standard_output_)
        throw InputError(errno != 0 ? fmt::format("cannot write to standard output: {}", std::strerror(errno))
                                    : "cannot write to standard output");
    }
  }
}

void OutputSet::move_into_place() {
  std::vector<fs::path> folders;
  for (auto& out : outputs_) {
    if (out->kind != Kind::file) continue;
    out->move_into_place();
    folders.push_back(out->target.parent_path().empty() ? fs::path(".") : out->target.parent_path());
  }
  // The renames are durable once their folders are on disk.
  for (const auto& dir : folders) {
    int dfd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (dfd >= 0) {
      ::fsync(dfd);
      ::close(dfd);
    }
  }
}

void OutputSet::reserve(std::string_view option, const std::string& path) { add_output(option, path).reserved = true; }

void OutputSet::fill(std::string_view option, std::string_view content) {
  for (auto& out : outputs_) {
    if (!out->reserved || out->filled || out->option != option) continue;
    remember_picture(out->svg, content);
    if (out->kind == Kind::file) out->stream->write(content.data(), static_cast<std::streamsize>(content.size()));
    else out->deferred.assign(content);
    out->filled = true;
    return;
  }
  throw std::logic_error(fmt::format("OutputSet::fill: no output reserved for '{}'", option));
}

void OutputSet::commit() {
  // A reserved output never filled is dropped: its destination stays as it was.
  std::erase_if(outputs_, [](const std::unique_ptr<Output>& out) { return out->reserved && !out->filled; });
  // Order: every temporary complete on disk, then the outputs that cannot be taken back
  // (standard output, devices), then the renames, which cannot fail for want of space.
  finish_temporaries();
  write_direct_outputs();
  move_into_place();
  outputs_.clear();
}

}  // namespace gearkit::io
