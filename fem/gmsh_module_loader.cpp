#include "fem/gmsh_module_loader.hpp"

#include <dlfcn.h>

#include <filesystem>
#include <mutex>
#include <stdexcept>
#include <string>
#include <system_error>

namespace flapsim::fem {
namespace {

namespace fs = std::filesystem;

/// Where the module is, or the first place it should have been (for the error).
fs::path find_module(bool& found) {
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  const fs::path beside = ec ? fs::path(kGmshModuleFile) : exe.parent_path() / kGmshModuleFile;
  found = true;
  if (!ec && fs::exists(beside, ec)) return beside;
#ifdef FLAPSIM_GMSH_MODULE_BUILD_PATH
  const fs::path built = FLAPSIM_GMSH_MODULE_BUILD_PATH;
  if (fs::exists(built, ec)) return built;
#endif
  found = false;
  return beside;
}

MeshWithGmshFn* load() {
  bool found = false;
  const fs::path path = find_module(found);
  const std::string what = "cannot mesh: flapsim's gmsh module " + path.string();
  if (!found) throw std::runtime_error(what + " is missing (install it next to the flapsim program)");
  void* module = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (module == nullptr) {
    const char* why = dlerror();
    throw std::runtime_error(what + " cannot be loaded: " + (why ? why : "unknown error"));
  }
  auto* version = reinterpret_cast<GmshBoundaryVersionFn*>(dlsym(module, kGmshBoundaryVersionSymbol));
  auto* mesh = reinterpret_cast<MeshWithGmshFn*>(dlsym(module, kMeshWithGmshSymbol));
  if (version == nullptr || mesh == nullptr || version() != kGmshBoundaryVersion)
    throw std::runtime_error(what + " is from another flapsim build (rebuild: make build)");
  return mesh;  // never unloaded: gmsh finalises at exit
}

}  // namespace

MeshWithGmshFn& gmsh_mesher() {
  static std::mutex m;
  static MeshWithGmshFn* mesh = nullptr;
  std::lock_guard<std::mutex> lock(m);
  if (mesh == nullptr) mesh = load();
  return *mesh;
}

}  // namespace flapsim::fem
