// The renderer loads OSMesa (and llvmpipe's libLLVM) when it first makes a context, not when a
// program that links it starts.
#include <gtest/gtest.h>
#include <link.h>

#include <string>

#include "cordgrasp/render/backend_info.h"

namespace cordgrasp {
namespace {

/// Is a shared object whose path contains `name` loaded in this process?
bool library_loaded(const std::string& name) {
  struct Search {
    std::string name;
    bool found = false;
  } search{name};
  dl_iterate_phdr(
      [](dl_phdr_info* info, size_t, void* data) {
        auto& s = *static_cast<Search*>(data);
        if (info->dlpi_name && std::string(info->dlpi_name).find(s.name) != std::string::npos)
          s.found = true;
        return 0;
      },
      &search);
  return search.found;
}

TEST(RenderLoading, OsMesaIsLoadedByTheFirstContextNotAtStart) {
  EXPECT_FALSE(library_loaded("libOSMesa"));
  EXPECT_FALSE(library_loaded("libLLVM"));
  // A context reports the GL version, or why there is none; either way OSMesa was opened.
  const std::string info = render_gl_info();
  ASSERT_EQ(info.find("OpenGL unavailable"), std::string::npos) << info;
  EXPECT_TRUE(library_loaded("libOSMesa")) << info;
}

}  // namespace
}  // namespace cordgrasp
