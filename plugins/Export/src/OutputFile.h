// SPDX-License-Identifier: MIT
// Where the Export plugin's components write: a `filename` as the scene gives it, relative to
// the working folder (as runSofa's), the folder checked at init so that an unwritable one is an
// error when the scene loads, not at the first write.
#pragma once

#include <filesystem>
#include <string>

namespace stroma {

class Base;

/// The path of `filename` with its extension `extension` (".vtu") removed when present, for
/// numbered names. Empty when filename is empty.
std::filesystem::path stripExtension(const std::string& filename, const std::string& extension);

/// Checks that the folder of `file` exists and accepts files; reports on `owner`'s `field`
/// otherwise and returns false.
bool checkOutputFolder(Base& owner, const std::filesystem::path& file, const std::string& field);

}  // namespace stroma
