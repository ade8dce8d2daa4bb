// rebuild_blender.py: which ops become the object's transform or stay live modifiers (no
// Blender), and, in real Blender, a script run in a user's scene adds one object in one new
// collection, changes nothing else, never exits Blender, and sits on the imported result.
#include "ops/blender_script.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/obj_io.h"
#include "core/surface_distance.h"
#include "ops/builders.h"
#include "tests/blender_runner.h"

namespace opgraph {
namespace {

namespace fs = std::filesystem;
using namespace build;

Sequence Build(const std::vector<Json>& ops) { return ParseSequence(Document(ops)); }

std::vector<bool> ObjectTransforms(const Sequence& sequence) {
  std::vector<bool> moved;
  for (const BlenderStepPlan& step : PlanBlenderSteps(sequence)) moved.push_back(step.object_transform);
  return moved;
}

Json TopExtrude() {
  ExtrudeArgs args;
  args.faces.normals = {Vec3d::UnitZ()};
  args.faces.expect = 1;
  args.height = 0.5;
  return Extrude(args);
}

Json CylinderCut() {
  BooleanArgs args;
  args.difference = true;
  args.primitive = Primitive::kCylinder;
  args.size = Vec3d(0.6, 0.6, 4);
  args.location = Vec3d(0.3, 0, 0);
  return Boolean(args);
}

TEST(BlenderPlan, TrailingTransformsBecomeTheObjectsAndModifiersStayLive) {
  const Sequence s = Build({TopExtrude(), Subdivision(2), Bevel(0.05, 2), GlobalRotate(Vec3d(90, 0, 30)),
                            GlobalTranslate(Vec3d(1, 2, 3))});
  EXPECT_EQ(ObjectTransforms(s), (std::vector<bool>{false, false, false, true, true}));
  EXPECT_EQ(LiveModifierNames(s), (std::vector<std::string>{"Subdivision", "Bevel"}));
}

TEST(BlenderPlan, TransformsMoveOnlyPastModifiersTheyCommuteWith) {
  // A scale changes a Bevel's width: it stays an edit, and applies nothing (no modifier before it).
  EXPECT_EQ(ObjectTransforms(Build({GlobalScale(Vec3d(1, 2, 1)), Bevel(0.1, 1)})), (std::vector<bool>{false, false}));
  // A rotation keeps it; Subdivision commutes with any affine map.
  EXPECT_EQ(ObjectTransforms(Build({GlobalRotate(Vec3d(0, 0, 45)), Bevel(0.1, 1)})), (std::vector<bool>{true, false}));
  EXPECT_EQ(ObjectTransforms(Build({GlobalScale(Vec3d(1, 2, 1)), Subdivision(1)})), (std::vector<bool>{true, false}));
  // A Boolean's cutter is placed in the frame after the transform; Mirror and SimpleDeform work
  // about the object's origin and axes.
  EXPECT_EQ(ObjectTransforms(Build({GlobalTranslate(Vec3d(0, 0, 1)), CylinderCut()})), (std::vector<bool>{false, false}));
  EXPECT_EQ(ObjectTransforms(Build({GlobalTranslate(Vec3d(0, 0, 1)), Mirror({Axis::kX})})), (std::vector<bool>{false, false}));
  EXPECT_EQ(ObjectTransforms(Build({GlobalRotate(Vec3d(0, 0, 1)), SimpleDeform(Deform::kTwist, Axis::kZ, 30)})),
            (std::vector<bool>{false, false}));
  // After a Boolean, anything goes: the cutter is the object's child.
  EXPECT_EQ(ObjectTransforms(Build({CylinderCut(), GlobalScale(Vec3d(2, 1, 1))})), (std::vector<bool>{false, true}));
}

TEST(BlenderPlan, AMeshEditAppliesTheModifiersAboveIt) {
  const Sequence s = Build({Subdivision(1), CylinderCut(), TopExtrude(), Subdivision(1)});
  const std::vector<BlenderStepPlan> plan = PlanBlenderSteps(s);
  EXPECT_EQ(plan[2].applies, (std::vector<size_t>{0, 1}));
  EXPECT_EQ(LiveModifierNames(s), (std::vector<std::string>{"Subdivision"}));
  const std::string script = BlenderScript(s);
  EXPECT_NE(script.find("Extrude edits the mesh data, so the modifiers above (Subdivision, Boolean) are applied first"),
            std::string::npos);
}

TEST(BlenderScriptOptions, NamesAndFramesAreChecked) {
  EXPECT_EQ(BlenderObjectName("my barrel (v2)"), "my barrel _v2_");
  EXPECT_EQ(BlenderObjectName("'; import os #"), "__ import os _");
  EXPECT_EQ(BlenderObjectName("..."), "opgraph");
  BlenderScriptOptions options;
  EXPECT_EQ(options.Check(), "");
  options.name = "a'b";
  EXPECT_NE(options.Check(), "");
  options.name = "ok";
  options.blender_from_sequence(0, 1) = 1;  // two ones in a row: not a permutation
  EXPECT_NE(options.Check(), "");
}

// The user's scene before and after: every object, collection and mesh they had, with what
// defines it; afterwards, what the script added.
constexpr const char* kRecordScene = R"PY(
import bpy, json, os
def state():
    objects = {o.name: {'type': o.type, 'matrix': [list(r) for r in o.matrix_world],
                        'data': o.data.name if o.data else None, 'hide': o.hide_get(),
                        'collections': sorted(c.name for c in o.users_collection),
                        'modifiers': [m.name for m in getattr(o, 'modifiers', [])]}
               for o in bpy.data.objects}
    meshes = {m.name: [round(sum(v.co[k] for v in m.vertices), 9) for k in range(3)] + [len(m.vertices)]
              for m in bpy.data.meshes}
    collections = {c.name: sorted(o.name for o in c.objects) for c in bpy.data.collections}
    return {'objects': objects, 'meshes': meshes, 'collections': collections,
            'scene_children': sorted(c.name for c in bpy.context.scene.collection.children)}
)PY";

constexpr const char* kUserScene = R"PY(
# A user's scene: the default cube, camera and light, plus their own object and collection that
# happen to have the names the script will want.
me = bpy.data.meshes.new('barrel')
me.from_pydata([(0, 0, 0), (1, 0, 0), (0, 1, 0)], [], [(0, 1, 2)])
theirs = bpy.data.objects.new('barrel', me)
bpy.context.scene.collection.objects.link(theirs)
theirs.modifiers.new('Subdivision', 'SUBSURF')
mine = bpy.data.collections.new('barrel')
bpy.context.scene.collection.children.link(mine)
bpy.data.objects['Cube'].location = (5, 0, 0)
bpy.data.objects['Cube'].select_set(True)
with open(os.environ['OPGRAPH_REPORT'] + '.before', 'w') as f:
    json.dump(state(), f)
)PY";

constexpr const char* kCheckScene = R"PY(
with open(os.environ['OPGRAPH_REPORT'] + '.before') as f:
    before = json.load(f)
after = json.loads(json.dumps(state()))  # as JSON, like `before`
report = {'lost': [], 'changed': [], 'added_objects': [], 'added_collections': [], 'orphans': []}
for kind in ('objects', 'meshes', 'collections'):
    for name, value in before[kind].items():
        if name not in after[kind]:
            report['lost'].append(name)
        elif after[kind][name] != value:
            report['changed'].append(name)
report['added_objects'] = sorted(set(after['objects']) - set(before['objects']))
report['added_collections'] = sorted(set(after['collections']) - set(before['collections']))
report['orphans'] = sorted(m.name for m in bpy.data.meshes if m.users == 0)
ours = [bpy.data.objects[n] for n in report['added_objects'] if bpy.data.objects[n].type == 'MESH'
        and bpy.data.objects[n].parent is None]
report['ours'] = [o.name for o in ours]
report['ours_collections'] = [sorted(c.name for c in o.users_collection) for o in ours]
report['modifiers'] = [[m.name for m in o.modifiers] for o in ours]
# Overlay: the result imported with Blender's default OBJ importer against our object, in world.
bpy.ops.wm.obj_import(filepath=os.environ['OPGRAPH_RESULT_OBJ'])
imported = bpy.context.selected_objects[0]
from mathutils import kdtree
tree = kdtree.KDTree(len(imported.data.vertices))
for v in imported.data.vertices:
    tree.insert(imported.matrix_world @ v.co, v.index)
tree.balance()
dg = bpy.context.evaluated_depsgraph_get()
evaluated = ours[0].evaluated_get(dg)
me = evaluated.to_mesh()
report['overlay_max'] = max(tree.find(ours[0].matrix_world @ v.co)[2] for v in me.vertices)
report['vertices'] = [len(me.vertices), len(imported.data.vertices)]
with open(os.environ['OPGRAPH_REPORT'], 'w') as f:
    json.dump(report, f)
)PY";

TEST(BlenderScript, RunInAUsersSceneAddsOneObjectAndChangesNothingElse) {
  const fs::path dir = fs::temp_directory_path() / "opgraph_blender_scene";
  fs::remove_all(dir);
  fs::create_directories(dir);
  Sequence sequence = Build({TopExtrude(), CylinderCut(), Subdivision(1), GlobalRotate(Vec3d(20, 0, 35)),
                             GlobalTranslate(Vec3d(0.5, -1, 2))});
  BlenderScriptOptions options;
  options.name = "barrel";
  options.blender_from_sequence << 1, 0, 0, 0, 0, -1, 0, 1, 0;  // Blender's OBJ importer: Y up
  const std::vector<Mesh> steps = EvaluateSequence(&sequence);
  WriteObj(steps.back(), (dir / "result.obj").string(), "result in the sequence's frame");
  std::ofstream(dir / "before.py") << kRecordScene << kUserScene;
  std::ofstream(dir / "rebuild_blender.py") << BlenderScript(sequence, options);
  std::ofstream(dir / "after.py") << kRecordScene << kCheckScene;
  // No "--": the script runs as from the Text editor; after.py runs only if Blender is still up.
  const std::string command = "OPGRAPH_RESULT_OBJ=" + ShellQuote((dir / "result.obj").string()) +
                              " OPGRAPH_REPORT=" + ShellQuote((dir / "report.json").string()) +
                              " blender -b --factory-startup --python-exit-code 1 --python " +
                              ShellQuote((dir / "before.py").string()) + " --python " +
                              ShellQuote((dir / "rebuild_blender.py").string()) + " --python " +
                              ShellQuote((dir / "after.py").string()) + " > " + ShellQuote((dir / "log").string()) +
                              " 2>&1";
  ASSERT_EQ(std::system(command.c_str()), 0) << command;
  std::ifstream in(dir / "report.json");
  ASSERT_TRUE(in) << "after.py did not run: the script ended Blender (see " << (dir / "log") << ")";
  const Json report = Json::parse(in);
  EXPECT_EQ(report["lost"], Json::array());
  EXPECT_EQ(report["changed"], Json::array());
  EXPECT_EQ(report["orphans"], Json::array());
  ASSERT_EQ(report["ours"].size(), 1u) << report.dump();
  EXPECT_EQ(report["ours"][0], "barrel.001");  // their "barrel" kept its name
  EXPECT_EQ(report["added_collections"], Json::array({"barrel.001"}));
  EXPECT_EQ(report["ours_collections"][0], Json::array({"barrel.001"}));
  // The object, its Boolean cutter (its child), nothing else.
  EXPECT_EQ(report["added_objects"].size(), 2u) << report.dump();
  EXPECT_EQ(report["modifiers"][0], Json::array({"Boolean", "Subdivision"}));
  // The two overlay: the transforms became the object's, and Blender's importer frame is matched.
  EXPECT_EQ(report["vertices"][0], report["vertices"][1]);
  EXPECT_LT(report["overlay_max"].get<double>(), 1e-6 * BoundingBoxDiagonal(steps.back()));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace opgraph
