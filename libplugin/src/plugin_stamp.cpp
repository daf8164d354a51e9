#include "plugin_stamp.hpp"

#include <elf.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <fmt/format.h>

#include <bit>
#include <cstring>
#include <vector>

namespace gearkit::plugin {

namespace {

constexpr const char* kSection = ".gearkit_plugin";

#if defined(__x86_64__)
constexpr int kMachine = EM_X86_64;
#elif defined(__aarch64__)
constexpr int kMachine = EM_AARCH64;
#else
constexpr int kMachine = -1;  // not checked
#endif

// Closes the descriptor on every path.
struct File {
  int fd = -1;
  ~File() {
    if (fd >= 0) ::close(fd);
  }
};

bool read_at(int fd, void* buffer, std::size_t size, std::uint64_t offset, std::uint64_t file_size) {
  if (offset > file_size || size > file_size - offset) return false;
  return ::pread(fd, buffer, size, static_cast<off_t>(offset)) == static_cast<ssize_t>(size);
}

// The section headers and the section-name table of a checked ELF header.
std::variant<std::vector<Elf64_Shdr>, std::string> section_headers(int fd, const Elf64_Ehdr& h, std::uint64_t size) {
  if (h.e_shentsize != sizeof(Elf64_Shdr) || h.e_shnum == 0 || h.e_shstrndx >= h.e_shnum)
    return std::string("has no usable section table (stripped of sections?)");
  std::vector<Elf64_Shdr> headers(h.e_shnum);
  if (!read_at(fd, headers.data(), headers.size() * sizeof(Elf64_Shdr), h.e_shoff, size))
    return std::string("is truncated (section table beyond the end of the file)");
  return headers;
}

std::variant<PluginStamp, std::string> find_stamp(int fd, const Elf64_Ehdr& h, std::uint64_t size) {
  auto table = section_headers(fd, h, size);
  if (auto* why = std::get_if<std::string>(&table)) return *why;
  const auto& headers = std::get<std::vector<Elf64_Shdr>>(table);
  const Elf64_Shdr& names = headers[h.e_shstrndx];
  if (names.sh_size > (1u << 20)) return std::string("has an oversized section-name table");
  std::vector<char> strings(names.sh_size + 1, '\0');
  if (!read_at(fd, strings.data(), names.sh_size, names.sh_offset, size))
    return std::string("is truncated (section names beyond the end of the file)");
  for (const Elf64_Shdr& s : headers) {
    if (s.sh_name >= names.sh_size || std::strcmp(strings.data() + s.sh_name, kSection) != 0) continue;
    PluginStamp stamp{};
    if (s.sh_size != sizeof(PluginStamp) || !read_at(fd, &stamp, sizeof stamp, s.sh_offset, size))
      return fmt::format("has a {} section of {} bytes, expected {}", kSection, s.sh_size, sizeof(PluginStamp));
    if (std::memcmp(stamp.magic, "gearkit", 8) != 0 || stamp.stamp_size != sizeof(PluginStamp))
      return fmt::format("has a {} section that is not a gearkit stamp", kSection);
    return stamp;
  }
  return fmt::format("has no gearkit plugin stamp (section {}): not a gearkit plugin, or one built for plugin API "
                     "2 or older; rebuild it against this gearkit", kSection);
}

}  // namespace

std::variant<PluginStamp, std::string> read_plugin_stamp(const std::filesystem::path& file) {
  // O_NONBLOCK: opening a FIFO must not wait for a writer; fstat then refuses it.
  File f{::open(file.c_str(), O_RDONLY | O_CLOEXEC | O_NOCTTY | O_NONBLOCK)};
  if (f.fd < 0) return fmt::format("cannot be opened: {}", std::strerror(errno));
  struct stat st {};
  if (::fstat(f.fd, &st) != 0 || !S_ISREG(st.st_mode))
    return std::string("is not a regular file (only regular files are loaded as plugins)");
  const auto size = static_cast<std::uint64_t>(st.st_size);
  Elf64_Ehdr h{};
  if (!read_at(f.fd, &h, sizeof h, 0, size) || std::memcmp(h.e_ident, ELFMAG, SELFMAG) != 0)
    return std::string("is not an ELF shared object (not a plugin module)");
  if (h.e_ident[EI_CLASS] != ELFCLASS64 || h.e_ident[EI_DATA] != (std::endian::native == std::endian::little ? ELFDATA2LSB : ELFDATA2MSB) ||
      (kMachine >= 0 && h.e_machine != kMachine))
    return std::string("is an ELF file for another machine, not a plugin for this gearkit");
  if (h.e_type != ET_DYN) return std::string("is an ELF file but not a shared object (not a plugin module)");
  return find_stamp(f.fd, h, size);
}

std::string stamp_mismatch(const PluginStamp& stamp) {
  if (stamp.api_version != kApiVersion)
    return fmt::format("built for plugin API version {}, this gearkit needs version {}; rebuild the plugin against "
                       "this gearkit", stamp.api_version, kApiVersion);
  if (stamp.command_abi != kCommandAbi)
    return fmt::format("built with another layout of the plugin interface (ABI fingerprint {:016x}, this gearkit "
                       "has {:016x}); rebuild the plugin against this gearkit with the same compiler",
                       stamp.command_abi, kCommandAbi);
  return {};
}

}  // namespace gearkit::plugin
