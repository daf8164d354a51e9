#include <gearkit/io/atomic_file.hpp>

#include <gearkit/io/output.hpp>

#include <iostream>

namespace gearkit::io {

void write_file_atomic(const std::string& path, std::string_view content, std::string_view option) {
  OutputSet outputs(std::cout);
  outputs.add(option, path, content);
  outputs.commit();
}

}  // namespace gearkit::io
