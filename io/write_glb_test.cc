// result.glb: Blender's own glTF importer reads one object per step, named after it, with its
// triangles, where Blender puts a Y-up file.
#include "io/write_glb.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "ops/params.h"

namespace opgraph {
namespace {

namespace fs = std::filesystem;

TEST(WriteGlb, BlendersImporterSeesEveryStep) {
  const fs::path dir = fs::temp_directory_path() / "opgraph_glb_test";
  fs::remove_all(dir);
  fs::create_directories(dir);
  Mesh cube = MakeCube(2.0);
  Mesh moved = cube;
  for (Vec3d& p : moved.vertices) p = Vec3d(p.x() + 3, 2 * p.y(), p.z() - 1);
  moved.faces.pop_back();  // open: 5 quads, 10 triangles
  {
    std::ofstream out(dir / "steps.glb", std::ios::binary);
    out << GlbBytes({cube, moved}, {"00_Start", "01_Moved"});
  }
  std::ofstream(dir / "check.py") << R"PY(
import bpy, json, os, sys
for o in list(bpy.data.objects):
    bpy.data.objects.remove(o)
# Debian's Blender 3.4 importer fails on its default shading guess with numpy >= 1.24 (np.bool).
bpy.ops.import_scene.gltf(filepath=sys.argv[-2], import_shading='FLAT')
report = {}
for o in bpy.data.objects:
    if o.type != 'MESH':
        continue
    corners = [o.matrix_world @ v.co for v in o.data.vertices]
    report[o.name] = {'triangles': len(o.data.polygons),
                      'lo': [min(c[k] for c in corners) for k in range(3)],
                      'hi': [max(c[k] for c in corners) for k in range(3)]}
with open(sys.argv[-1], 'w') as f:
    json.dump(report, f)
)PY";
  const std::string command = "blender -b --factory-startup --python-exit-code 1 -P '" + (dir / "check.py").string() +
                              "' -- '" + (dir / "steps.glb").string() + "' '" + (dir / "report.json").string() +
                              "' > '" + (dir / "log").string() + "' 2>&1";
  ASSERT_EQ(std::system(command.c_str()), 0) << command;
  const Json report = Json::parse(std::ifstream(dir / "report.json"));
  ASSERT_TRUE(report.contains("00_Start") && report.contains("01_Moved")) << report.dump();
  EXPECT_EQ(report["00_Start"]["triangles"], 12);
  EXPECT_EQ(report["01_Moved"]["triangles"], 10);
  // glTF is +Y up: Blender's (x, y, z) is the file's (x, -z, y).
  const Json& box = report["01_Moved"];
  const double expected_lo[3] = {2, 0, -2}, expected_hi[3] = {4, 2, 2};
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(box["lo"][k].get<double>(), expected_lo[k], 1e-6) << k;
    EXPECT_NEAR(box["hi"][k].get<double>(), expected_hi[k], 1e-6) << k;
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace opgraph
