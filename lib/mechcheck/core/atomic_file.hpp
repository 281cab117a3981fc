#pragma once
/// Writing a file so that a reader never sees half of it.

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

namespace mechcheck {

/// Writes `content` to `path` through path + ".tmp" and a rename: an interrupted writer
/// leaves the old file (or none), never a truncated one. Throws std::runtime_error naming
/// the file when it cannot be written.
inline void write_file_atomically(const std::filesystem::path& path, const std::string& content) {
  const std::filesystem::path tmp = path.string() + ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    out << content;
    out.flush();
    if (!out) throw std::runtime_error("cannot write " + tmp.string());
  }
  std::filesystem::rename(tmp, path);
}

}  // namespace mechcheck
