#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "manifest.h"
#include "test_paths.h"

namespace cordgrasp {
namespace {

TEST(CliInfoObjectDataset, JsonIsValidWithManifestCountsForEveryObject) {
  CORDGRASP_REQUIRE_SHARED_DATA();
  const auto objects = test::manifest_objects();
  ASSERT_FALSE(objects.empty());
  for (const auto& o : objects) {
    SCOPED_TRACE(o.file);
    const test::CommandResult r = test::run_cordgrasp(
        "info --json --object \"" + test::shared_data_dir() + "/" + o.file + "\"");
    ASSERT_EQ(r.exit_code, 0) << r.output;
    nlohmann::json j;
    ASSERT_NO_THROW(j = nlohmann::json::parse(r.output)) << r.output;
    EXPECT_EQ(j["triangles"].get<int>() + j["degenerate_dropped"].get<int>(), o.triangles);
    EXPECT_EQ(j["topology"]["closed"].get<bool>(), o.watertight);
    EXPECT_EQ(j["topology"]["components"].get<int>(), o.components);
    EXPECT_EQ(j["volume_m3"].is_null(), !o.watertight);
    EXPECT_GT(j["convex_hull_volume_m3"].get<double>(), 0.0);
  }
}

}  // namespace
}  // namespace cordgrasp
