// The loader of the OpenCASCADE plugin (core/detail/opencascade_plugin.hpp); empty in a library
// built without OpenCASCADE.
#if CAGD_WITH_OPENCASCADE
#include "cagd/core/detail/opencascade_plugin.hpp"

#include <dlfcn.h>

#include <cstdlib>
#include <filesystem>
#include <mutex>

#include "cagd/core/errors.hpp"

namespace cagd::detail {

namespace {

constexpr const char* kPluginFile = "libcagd_occt.so";

struct Loaded {
    const OpenCascadePlugin* plugin = nullptr;
    std::string looked;  // every place looked at, and why each was not taken
};

// Appends "; <path> (<why>)" to `looked` (appends, not operator+: GCC 12 warns falsely of an
// overlapping memcpy in a chain of string concatenations).
void note(std::string& looked, const std::filesystem::path& path, const std::string& why) {
    looked.append("; ").append(path.string()).append(" (").append(why).append(")");
}

// The plugin at `path`, or null with the reason appended to `looked`.
const OpenCascadePlugin* try_load(const std::filesystem::path& path, std::string& looked) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) {
        note(looked, path, "absent");
        return nullptr;
    }
    void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!handle) {
        note(looked, path, dlerror());
        return nullptr;
    }
    using Entry = const OpenCascadePlugin* (*)();
    const auto entry = reinterpret_cast<Entry>(dlsym(handle, "cagd_opencascade_plugin"));
    const OpenCascadePlugin* plugin = entry ? entry() : nullptr;
    if (!plugin || !plugin->interface || std::string(plugin->interface) != kOpenCascadePluginInterface) {
        note(looked, path,
             std::string("another build: ").append(plugin && plugin->interface ? plugin->interface : "no interface"));
        dlclose(handle);
        return nullptr;
    }
    return plugin;  // kept loaded for the life of the process
}

Loaded load() {
    Loaded l;
    std::vector<std::filesystem::path> candidates;
    if (const char* named = std::getenv("CAGD_OCCT_PLUGIN"); named && *named) candidates.emplace_back(named);
    Dl_info self{};
    if (dladdr(reinterpret_cast<const void*>(&opencascade_plugin), &self) && self.dli_fname) {
        const std::filesystem::path binary = std::filesystem::weakly_canonical(self.dli_fname);
        candidates.push_back(binary.parent_path() / kPluginFile);
        candidates.push_back(binary.parent_path().parent_path() / CAGD_OCCT_PLUGIN_LIBDIR / "cagd" / kPluginFile);
    }
    candidates.emplace_back(CAGD_OCCT_PLUGIN_INSTALL_PATH);
    candidates.emplace_back(CAGD_OCCT_PLUGIN_BUILD_PATH);
    for (const auto& c : candidates)
        if ((l.plugin = try_load(c, l.looked))) break;
    return l;
}

}  // namespace

const OpenCascadePlugin& opencascade_plugin(const std::string& who) {
    static std::once_flag once;
    static Loaded loaded;
    std::call_once(once, [] { loaded = load(); });
    if (!loaded.plugin)
        fail_input(who, std::string("needs OpenCASCADE through the plugin ")
                            .append(kPluginFile)
                            .append(", which could not be loaded (looked at")
                            .append(loaded.looked.substr(1))
                            .append("; the environment variable CAGD_OCCT_PLUGIN names it)"));
    return *loaded.plugin;
}

}  // namespace cagd::detail
#endif
