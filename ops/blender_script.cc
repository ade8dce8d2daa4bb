#include "ops/blender_script.h"

#include <cctype>
#include <cmath>
#include <sstream>

#include "ops/face_selector.h"
#include "ops/global_affine.h"
#include "ops/vertex_selector.h"

namespace opgraph {

namespace {

bool NameCharacter(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) || c == ' ' || c == '_' || c == '-' || c == '.';
}

constexpr size_t kMaxNameLength = 48;  // Blender keeps 63 bytes and may add ".001"

// Helpers shared by every op's Blender code.
const char* kBlenderPreamble = R"PY(# Rebuilds an opgraph design sequence with Blender's own operators and modifiers.
#
# In a scene: run it from Blender's Text editor, or `blender FILE.blend --python rebuild_blender.py`.
# It adds one object in a new collection, both named after the input, and changes nothing else.
#
# Headless: blender -b --factory-startup --python-exit-code 1 -P rebuild_blender.py -- OUT.obj
# also writes the evaluated mesh to OUT.obj in the sequence's frame (no importer axis conversion).
import os
import sys

import bmesh
import bpy
from mathutils import Euler, Matrix, Vector


def new_object(name, size):
    """A cube object `name` in a new collection `name`: the only things this script adds."""
    collection = bpy.data.collections.new(name)
    bpy.context.scene.collection.children.link(collection)
    me = bpy.data.meshes.new(name)
    bm = bmesh.new()
    bmesh.ops.create_cube(bm, size=size)
    bm.to_mesh(me)
    bm.free()
    obj = bpy.data.objects.new(name, me)
    collection.objects.link(obj)
    return obj, collection


def edit_mesh(obj):
    """Mesh data for a destructive edit: pending modifiers are applied first."""
    if len(obj.modifiers):
        dg = bpy.context.evaluated_depsgraph_get()
        me = bpy.data.meshes.new_from_object(obj.evaluated_get(dg))
        obj.modifiers.clear()
        old = obj.data
        obj.data = me
        bpy.data.meshes.remove(old)
    return obj.data


def open_bmesh(obj):
    """(mesh, bmesh) for a bmesh edit; pair with close_bmesh."""
    me = edit_mesh(obj)
    bm = bmesh.new()
    bm.from_mesh(me)
    return me, bm


def close_bmesh(me, bm):
    bm.to_mesh(me)
    bm.free()
    me.update()


def finish(obj, frame, pose):
    """The sequence's trailing transforms become the object's, in Blender's frame for the input."""
    obj.matrix_world = frame @ pose
    bpy.context.view_layer.objects.active = obj


def export_obj(obj, path, pose):
    """The evaluated mesh in the sequence's frame, and the live modifiers as comments."""
    dg = bpy.context.evaluated_depsgraph_get()
    evaluated = obj.evaluated_get(dg)
    me = evaluated.to_mesh()
    lines = ['# opgraph rebuild_blender.py, Blender %s' % bpy.app.version_string]
    lines += ['# modifier %s' % m.name for m in obj.modifiers]
    lines += ['v %.9g %.9g %.9g' % tuple(pose @ v.co) for v in me.vertices]
    lines += ['f ' + ' '.join(str(i + 1) for i in p.vertices) for p in me.polygons]
    evaluated.to_mesh_clear()
    tmp = path + '.tmp'
    with open(tmp, 'w') as f:
        f.write('\n'.join(lines) + '\n')
    os.replace(tmp, path)


# Run from a scene there are no arguments: build the object and stop (never exit Blender). A
# caller that runs this file itself (the add-on) sets OPGRAPH_ARGV.
argv = sys.argv[sys.argv.index('--') + 1:] if '--' in sys.argv else []
argv = globals().get('OPGRAPH_ARGV', argv)
if len(argv) > 1:
    raise RuntimeError('usage: blender -b --factory-startup --python-exit-code 1 -P rebuild_blender.py -- OUT.obj')
)PY";

std::string PyMatrix3(const Eigen::Matrix3d& m) {
  std::string rows;
  for (int r = 0; r < 3; ++r) {
    rows += "(" + Py(m(r, 0)) + ", " + Py(m(r, 1)) + ", " + Py(m(r, 2)) + ", 0.0), ";
  }
  return "Matrix((" + rows + "(0.0, 0.0, 0.0, 1.0)))";
}

std::string ModifierList(const Sequence& sequence, const std::vector<size_t>& indices) {
  std::string names;
  for (size_t i : indices) names += (names.empty() ? "" : ", ") + sequence.ops[i]->Name();
  return names;
}

}  // namespace

std::string BlenderObjectName(const std::string& text) {
  std::string name;
  for (char c : text.substr(0, kMaxNameLength)) name += NameCharacter(c) ? c : '_';
  return name.find_first_not_of(" ._-") == std::string::npos ? "opgraph" : name;
}

std::string BlenderScriptOptions::Check() const {
  if (name.empty() || name.size() > kMaxNameLength) return "name: must have 1 to 48 characters";
  for (char c : name) {
    if (!NameCharacter(c)) return "name: only letters, digits, ' ', '_', '-' and '.'";
  }
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) {
      const double v = blender_from_sequence(r, c);
      if (v != 0 && v != 1 && v != -1) return "blender_from_sequence: must be a signed permutation";
    }
  }
  if ((blender_from_sequence.transpose() * blender_from_sequence - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff() != 0) {
    return "blender_from_sequence: must be a signed permutation";
  }
  return "";
}

std::vector<BlenderStepPlan> PlanBlenderSteps(const Sequence& sequence) {
  const size_t n = sequence.ops.size();
  std::vector<BlenderStepPlan> plan(n);
  // Backwards: a transform may move to the end while every later op is a modifier it commutes
  // with (or a transform that moves too: their order is kept).
  bool movable_rigid = true;
  bool movable_any = true;
  for (size_t k = n; k-- > 0;) {
    const Op& op = *sequence.ops[k];
    switch (op.Stage()) {
      case BlenderStage::kTransform: {
        const auto* affine = dynamic_cast<const GlobalAffineOp*>(&op);
        plan[k].object_transform = affine != nullptr && (affine->rigid() ? movable_rigid : movable_any);
        if (!plan[k].object_transform) movable_rigid = movable_any = false;
        break;
      }
      case BlenderStage::kModifier:
        movable_rigid = movable_rigid && op.CommutesWithTransform(true);
        movable_any = movable_any && op.CommutesWithTransform(false);
        break;
      case BlenderStage::kMeshEdit:
        movable_rigid = movable_any = false;
        break;
    }
  }
  // Forwards: which modifiers each mesh edit applies, and which stay live.
  std::vector<size_t> pending;
  for (size_t k = 0; k < n; ++k) {
    const BlenderStage stage = sequence.ops[k]->Stage();
    if (stage == BlenderStage::kModifier) {
      pending.push_back(k);
    } else if (!plan[k].object_transform) {
      plan[k].applies = pending;
      pending.clear();
    }
  }
  for (size_t k : pending) plan[k].live_modifier = true;
  return plan;
}

std::vector<std::string> LiveModifierNames(const Sequence& sequence) {
  const std::vector<BlenderStepPlan> plan = PlanBlenderSteps(sequence);
  std::vector<std::string> names;
  for (size_t k = 0; k < plan.size(); ++k) {
    if (plan[k].live_modifier) names.push_back(sequence.ops[k]->Name());
  }
  return names;
}

std::string BlenderScript(const Sequence& sequence, const BlenderScriptOptions& options) {
  const std::string problem = options.Check();
  if (!problem.empty()) throw SequenceError("Blender script options: " + problem);
  const std::vector<BlenderStepPlan> plan = PlanBlenderSteps(sequence);
  std::ostringstream script;
  script << kBlenderPreamble << kVertexSelectorPython << "\nkMinFaceShape = " << Py(kMinFaceShape) << "\n"
         << kFaceSelectorPython << "\n\nobj, collection = new_object('" << options.name << "', "
         << Py(sequence.start_size) << ")\n"
         << "pose = Matrix.Identity(4)  # the sequence's transforms that become the object's\n";
  for (size_t i = 0; i < sequence.ops.size(); ++i) {
    const Op& op = *sequence.ops[i];
    if (sequence.gates[i] != 1.0) {
      throw SequenceError("operation " + std::to_string(i) + " (" + op.Name() +
                          "): field 'gate': Blender export needs gate 1 (run the fitter's finalisation first)");
    }
    script << "\n# " << i << ": " << op.Name() << "\n";
    if (plan[i].object_transform) {
      script << "# Only modifiers it commutes with follow: it becomes the object's transform, so they stay live.\n"
             << "pose = " << dynamic_cast<const GlobalAffineOp&>(op).PyMatrix() << " @ pose\n";
      continue;
    }
    if (!plan[i].applies.empty()) {
      script << "# " << op.Name() << " edits the mesh data, so the modifiers above ("
             << ModifierList(sequence, plan[i].applies) << ") are applied first.\n";
    }
    script << op.BlenderCode();
  }
  script << "\nfinish(obj, " << PyMatrix3(options.blender_from_sequence) << ", pose)\n"
         << "if argv:\n    export_obj(obj, argv[0], pose)\n";
  return script.str();
}

}  // namespace opgraph
