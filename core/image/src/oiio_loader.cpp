// Finds and loads the OpenImageIO module: dlopen is the only way into it, so that a program
// that never needs OpenImageIO never loads it (oiio_module.h).
#include "oiio_module.h"

#include <cstddef>
#include <cstdlib>
#include <cstring>
#include <dlfcn.h>
#include <filesystem>
#include <string>
#include <system_error>
#include <vector>

#ifndef STRAHLER_IMAGE_MODULE_INSTALL_DIR
#error "core/image/CMakeLists.txt defines STRAHLER_IMAGE_MODULE_INSTALL_DIR"
#endif

namespace strahler::image::detail {
namespace {

namespace fs = std::filesystem;
using base::ErrorCode;
using base::makeError;

/// What the module is for, appended to every loading error so that the user knows what fails.
constexpr const char* kNeededFor =
    "OpenImageIO is needed for float TIFF/EXR tiles, image files and PNG pictures";

/// dlerror()'s text, which names `file` first (it names only a missing dependency otherwise).
std::string lastDlError(const std::string& file) {
  const char* text = dlerror();
  const std::string message = text ? std::string(text) : std::string("unknown dlopen error");
  return message.rfind(file, 0) == 0 ? message : file + ": " + message;
}

/// The folders of the program's library search path (its RUNPATH, which CMake gives the build
/// tree's test programs; LD_LIBRARY_PATH; the system's), absolute ones only. Asked of the
/// dynamic loader with dlinfo rather than left to a dlopen by bare name, which searches the
/// RUNPATH of its caller: under AddressSanitizer that is the sanitizer's runtime, not us.
std::vector<fs::path> libraryPath() {
  void* program = dlopen(nullptr, RTLD_LAZY);
  if (program == nullptr)
    return {};
  std::vector<fs::path> folders;
  Dl_serinfo size{};
  if (dlinfo(program, RTLD_DI_SERINFOSIZE, &size) == 0 && size.dls_size >= sizeof(Dl_serinfo)) {
    // dlinfo fills a Dl_serinfo followed by its strings in one block of dls_size bytes.
    std::vector<std::max_align_t> block(size.dls_size / sizeof(std::max_align_t) + 1);
    auto* info = reinterpret_cast<Dl_serinfo*>(block.data());
    if (dlinfo(program, RTLD_DI_SERINFOSIZE, info) == 0 &&
        dlinfo(program, RTLD_DI_SERINFO, info) == 0)
      for (unsigned i = 0; i < info->dls_cnt; ++i)
        if (const char* name = info->dls_serpath[i].dls_name; name != nullptr && name[0] == '/')
          folders.emplace_back(name);
  }
  dlclose(program);
  return folders;
}

/// The folders to look in, in order: $STRAHLER_MODULE_DIR alone when set, else the folder of
/// the running program (the build tree keeps the module beside bin/strahler), the install
/// folder relative to it (bin/../lib/strahler after `cmake --install`), and the program's
/// library search path.
std::vector<fs::path> searchFolders(bool& fromEnvironment) {
  if (const char* dir = std::getenv("STRAHLER_MODULE_DIR"); dir != nullptr && *dir != '\0') {
    fromEnvironment = true;
    return {fs::path(dir)};
  }
  fromEnvironment = false;
  std::vector<fs::path> folders;
  std::error_code ec;
  const fs::path executable = fs::read_symlink("/proc/self/exe", ec);
  if (!ec && !executable.empty()) {
    const fs::path folder = executable.parent_path();
    folders = {folder, (folder / STRAHLER_IMAGE_MODULE_INSTALL_DIR).lexically_normal()};
  }
  for (fs::path& folder : libraryPath())
    folders.push_back(std::move(folder));
  return folders;
}

/// Opens `file` (a path) and checks that it was built from the same interface with the same C++
/// ABI; every error names `file`.
base::Result<const OiioModule*> openModule(const std::string& file) {
  dlerror();
  // RTLD_LOCAL: OpenImageIO's symbols (and its libraries') stay out of the global scope.
  void* handle = dlopen(file.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (handle == nullptr)
    return makeError(ErrorCode::kUnsupported, lastDlError(file));
  const auto abi = reinterpret_cast<OiioAbiFunction>(dlsym(handle, kOiioAbiSymbol));
  const auto entry = reinterpret_cast<OiioModuleFunction>(dlsym(handle, kOiioModuleSymbol));
  if (abi == nullptr || entry == nullptr) {
    dlclose(handle);
    return makeError(ErrorCode::kUnsupported, file + " is not a strahler image module");
  }
  if (std::strcmp(abi(), STRAHLER_IMAGE_OIIO_ABI) != 0) {
    const std::string built = abi();
    dlclose(handle);
    return makeError(ErrorCode::kUnsupported, file + " was built for another strahler (" + built +
                                                  "; this program: " STRAHLER_IMAGE_OIIO_ABI ")");
  }
  // Never closed: the module stays until the process exits.
  const OiioModule* module = entry();
  if (module == nullptr)
    return makeError(ErrorCode::kUnsupported, file + " returned no module");
  return module;
}

base::Result<const OiioModule*> loadModule() {
  bool fromEnvironment = false;
  const std::vector<fs::path> folders = searchFolders(fromEnvironment);
  std::string searched;
  for (std::size_t i = 0; i < folders.size(); ++i) {
    const fs::path file = folders[i] / kOiioModuleFile;
    std::error_code ec;
    if (fs::exists(file, ec)) {
      // The first module found is the one: if it does not load, say why rather than try others.
      auto module = openModule(file.string());
      if (!module)
        return makeError(ErrorCode::kUnsupported,
                         "cannot load the OpenImageIO module: " + module.error().message + " (" +
                             kNeededFor + ")");
      return module;
    }
    // The message names the program's own folders; the library path is summed up.
    if (i < 2 || fromEnvironment)
      searched += (searched.empty() ? "" : ", ") + folders[i].string();
  }
  return makeError(
      ErrorCode::kUnsupported,
      std::string("the OpenImageIO module ") + kOiioModuleFile + " is not in " +
          (searched.empty() ? std::string("the program's folder") : searched) +
          (fromEnvironment ? " ($STRAHLER_MODULE_DIR)" : " nor in the program's library path") +
          " (" + kNeededFor + ")");
}

} // namespace

const base::Result<const OiioModule*>& oiioModule() {
  static const base::Result<const OiioModule*> module = loadModule();
  return module;
}

} // namespace strahler::image::detail
