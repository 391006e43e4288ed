// Outputs are written to a temporary file beside the target and renamed into place, so an
// interrupted or failed run never leaves a truncated file under the final name.
#pragma once
#include <functional>
#include <string>

namespace gdr {

// Calls `write(tmp_path)`; on success renames tmp_path to `path`, on any exception removes it
// and rethrows. The temporary name keeps the extension (image writers choose the format by it).
void write_file_atomically(const std::string& path,
                           const std::function<void(const std::string& tmp_path)>& write);

void write_text_file(const std::string& path, const std::string& text);

}  // namespace gdr
