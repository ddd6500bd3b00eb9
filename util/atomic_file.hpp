#pragma once
// Outputs are written atomically: to a temporary file beside the target, then renamed,
// so a failure never leaves a half-written file under the final name.
#include <filesystem>
#include <functional>
#include <string>

namespace lfd {

// Calls `write(tmp_path)`, then renames tmp_path to `path`. Creates parent directories.
// On any exception the temporary file is removed and the exception propagates.
void write_file_atomic(const std::filesystem::path& path,
                       const std::function<void(const std::filesystem::path&)>& write);

// Writes `text` to `path` atomically.
void write_text_atomic(const std::filesystem::path& path, const std::string& text);

// Reads a whole text file; throws InputError naming the file if it cannot be read.
std::string read_text_file(const std::filesystem::path& path);

// Refuses to replace an existing file unless `force`; with `force`, keeps `path.bak`.
void guard_overwrite(const std::filesystem::path& path, bool force);

}  // namespace lfd
