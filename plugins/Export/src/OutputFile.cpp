// SPDX-License-Identifier: MIT
#include "OutputFile.h"

#include <fstream>

#include "core/Base.h"

namespace stroma {

namespace fs = std::filesystem;

fs::path stripExtension(const std::string& filename, const std::string& extension) {
  if (!extension.empty() && filename.size() > extension.size() && filename.ends_with(extension))
    return filename.substr(0, filename.size() - extension.size());
  return filename;
}

bool checkOutputFolder(Base& owner, const fs::path& file, const std::string& field) {
  if (file.empty()) {
    owner.msgError("no file name given", field);
    return false;
  }
  const fs::path folder = file.parent_path().empty() ? fs::path(".") : file.parent_path();
  std::error_code ec;
  if (!fs::is_directory(folder, ec)) {
    owner.msgError("folder '" + folder.string() + "' of '" + file.string() + "' does not exist",
                   field);
    return false;
  }
  const fs::path probe = folder / ".stroma-write-test";
  bool writable = false;
  {
    std::ofstream test(probe);
    writable = static_cast<bool>(test);
  }
  fs::remove(probe, ec);
  if (!writable) {
    owner.msgError("cannot write files in folder '" + folder.string() + "'", field);
    return false;
  }
  return true;
}

}  // namespace stroma
