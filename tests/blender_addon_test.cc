// The Blender add-on, installed as a user would (Preferences > Add-ons > Install, into a
// throw-away user scripts folder), run headless on the bundled barrel: a new object in its own
// collection, with a live modifier stack, on top of the source.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "ops/params.h"

namespace opgraph {
namespace {

namespace fs = std::filesystem;

constexpr const char* kDriveAddon = R"PY(
import bpy, json, sys
addon, fit_sequence, source, report_path = sys.argv[-4:]
bpy.ops.preferences.addon_install(filepath=addon)
bpy.ops.preferences.addon_enable(module='opgraph_addon')
bpy.context.preferences.addons['opgraph_addon'].preferences.fit_sequence = fit_sequence
bpy.ops.wm.obj_import(filepath=source)
src = bpy.context.selected_objects[0]
bpy.context.view_layer.objects.active = src
before = set(bpy.data.objects.keys())
in_menu = 'opgraph_recover' in dir(bpy.ops.object)
result = bpy.ops.object.opgraph_recover(work_budget=3000)
new = [bpy.data.objects[n] for n in bpy.data.objects.keys() if n not in before]
ours = [o for o in new if o.parent is None]
def world_box(obj):
    dg = bpy.context.evaluated_depsgraph_get()
    ev = obj.evaluated_get(dg)
    me = ev.to_mesh()
    points = [obj.matrix_world @ v.co for v in me.vertices]
    box = [[min(p[k] for p in points) for k in range(3)], [max(p[k] for p in points) for k in range(3)]]
    ev.to_mesh_clear()
    return box
report = {'result': sorted(result), 'in_menu': in_menu, 'ours': [o.name for o in ours],
          'collections': [[c.name for c in o.users_collection] for o in ours],
          'modifiers': [[m.type for m in o.modifiers] for o in ours],
          'source_box': world_box(src), 'source_name': src.name}
if ours:
    report['box'] = world_box(ours[0])
with open(report_path, 'w') as f:
    json.dump(report, f)
)PY";

TEST(BlenderAddon, RecoversTheBarrelInBlender) {
  const fs::path dir = fs::temp_directory_path() / "opgraph_addon_test";
  fs::remove_all(dir);
  fs::create_directories(dir / "user_scripts");
  std::ofstream(dir / "drive.py") << kDriveAddon;
  const std::string source_dir = OPGRAPH_SOURCE_DIR;
  const std::string command = "BLENDER_USER_SCRIPTS='" + (dir / "user_scripts").string() +
                              "' blender -b --factory-startup --python-exit-code 1 -P '" + (dir / "drive.py").string() +
                              "' -- '" + source_dir + "/blender/opgraph_addon.py' '" + OPGRAPH_FIT_SEQUENCE + "' '" +
                              source_dir + "/examples/barrel.obj' '" + (dir / "report.json").string() + "' > '" +
                              (dir / "log").string() + "' 2>&1";
  ASSERT_EQ(std::system(command.c_str()), 0) << command;
  const Json report = Json::parse(std::ifstream(dir / "report.json"));
  EXPECT_TRUE(report["in_menu"].get<bool>());
  EXPECT_EQ(report["result"], Json::array({"FINISHED"}));
  ASSERT_EQ(report["ours"].size(), 1u) << report.dump();
  // Named after the source, in a collection of its own.
  EXPECT_EQ(report["ours"][0].get<std::string>().rfind(report["source_name"].get<std::string>(), 0), 0u);
  ASSERT_EQ(report["collections"][0].size(), 1u);
  EXPECT_EQ(report["collections"][0][0].get<std::string>().rfind(report["source_name"].get<std::string>(), 0), 0u);
  EXPECT_FALSE(report["modifiers"][0].empty()) << "no live modifier: " << report.dump();
  // On top of the source: bounding boxes within 5% of the source's diagonal.
  double diagonal = 0;
  for (int k = 0; k < 3; ++k) {
    const double side = report["source_box"][1][k].get<double>() - report["source_box"][0][k].get<double>();
    diagonal += side * side;
  }
  diagonal = std::sqrt(diagonal);
  for (int end = 0; end < 2; ++end) {
    for (int k = 0; k < 3; ++k) {
      EXPECT_NEAR(report["box"][end][k].get<double>(), report["source_box"][end][k].get<double>(), 0.05 * diagonal)
          << "end " << end << " axis " << k;
    }
  }
  // Installed into the throw-away user folder, not the user's Blender.
  EXPECT_TRUE(fs::exists(dir / "user_scripts" / "addons" / "opgraph_addon.py"));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace opgraph
