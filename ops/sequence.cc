#include "ops/sequence.h"

#include "core/printable.h"
#include "ops/face_selector.h"
#include "ops/vertex_selector.h"

#include <fstream>
#include <sstream>

namespace opgraph {

namespace {

std::string OpLabel(size_t index, const std::string& name) {
  return "operation " + std::to_string(index) + " (" + Printable(name) + ")";
}

}  // namespace

Sequence ParseSequence(const Json& document) {
  Sequence sequence;
  if (!document.is_object()) throw SequenceError("sequence: top level must be a JSON object");
  for (auto it = document.begin(); it != document.end(); ++it) {
    static const char* const kKeys[] = {"format", "version", "start", "operations", "name", "description"};
    if (std::find(std::begin(kKeys), std::end(kKeys), it.key()) == std::end(kKeys)) {
      throw SequenceError("sequence: field '" + Printable(it.key()) + "': unknown field");
    }
  }
  if (document.contains("format") && document["format"] != "opgraph-sequence") {
    throw SequenceError("sequence: field 'format': must be \"opgraph-sequence\"");
  }
  for (const char* text : {"name", "description"}) {
    if (document.contains(text) && !document[text].is_string()) {
      throw SequenceError(std::string("sequence: field '") + text + "': must be a string");
    }
  }
  if (document.contains("version")) {
    const Json& v = document["version"];
    // Compared as JSON values: 4294967297 is not 1 (a conversion to int would wrap it).
    if (!v.is_number_integer() || v != Json(kSequenceFormatVersion)) {
      throw SequenceError("sequence: field 'version': unsupported (this build reads version " +
                          std::to_string(kSequenceFormatVersion) + ")");
    }
  }
  if (document.contains("start")) {
    try {
      ParamReader start(document["start"]);
      start.Word("primitive", {"cube"});
      sequence.start_size = start.Number("size", 1e-6, 1e6, 2.0);
      start.Finish();
    } catch (const FieldError& e) {
      throw SequenceError("sequence: start: field '" + e.field() + "': " + e.what());
    }
  }
  if (!document.contains("operations") || !document["operations"].is_array()) {
    throw SequenceError("sequence: field 'operations': missing or not an array");
  }
  const Json& operations = document["operations"];
  for (size_t i = 0; i < operations.size(); ++i) {
    const Json& entry = operations[i];
    if (!entry.is_object() || !entry.contains("op") || !entry["op"].is_string()) {
      throw SequenceError(OpLabel(i, "?") + ": field 'op': missing or not a string");
    }
    const std::string name = entry["op"].get<std::string>();
    try {
      for (auto it = entry.begin(); it != entry.end(); ++it) {
        if (it.key() != "op" && it.key() != "params" && it.key() != "gate") {
          throw FieldError(Printable(it.key()), "unknown field");
        }
      }
      const Json params = entry.contains("params") ? entry["params"] : Json::object();
      sequence.ops.push_back(CreateOp(name, params));
      sequence.gates.push_back(entry.contains("gate") ? CheckedNumber(entry["gate"], "gate", 0, 1) : 1.0);
    } catch (const FieldError& e) {
      throw SequenceError(OpLabel(i, name) + ": field '" + e.field() + "': " + e.what());
    } catch (const std::invalid_argument& e) {
      throw SequenceError(OpLabel(i, name) + ": field 'op': " + e.what());
    }
  }
  return sequence;
}

Sequence LoadSequence(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw SequenceError(path + ": cannot open file");
  Json document;
  try {
    document = Json::parse(in);
  } catch (const Json::parse_error& e) {
    std::string what = e.what();
    throw SequenceError(path + ": invalid JSON: " + what.substr(what.find(']') + 2));
  }
  return ParseSequence(document);
}

Json SequenceToJson(const Sequence& sequence) {
  Json ops = Json::array();
  for (size_t i = 0; i < sequence.ops.size(); ++i) {
    Json entry = {{"op", sequence.ops[i]->Name()}, {"params", sequence.ops[i]->ParamsToJson()}};
    if (sequence.gates[i] != 1.0) entry["gate"] = sequence.gates[i];
    ops.push_back(entry);
  }
  return {{"format", "opgraph-sequence"},
          {"version", kSequenceFormatVersion},
          {"start", {{"primitive", "cube"}, {"size", sequence.start_size}}},
          {"operations", ops}};
}

Mesh ApplyOp(Op* op, double gate, const Mesh& input) {
  op->Prepare(input);
  Mesh next;
  op->Evaluate(op->params().data(), gate, input.vertices, &next.vertices);
  next.faces = op->OutputFaces(gate);
  return next;
}

std::vector<Mesh> EvaluateSequence(Sequence* sequence) {
  std::vector<Mesh> steps;
  Mesh current = sequence->StartMesh();
  int64_t total_faces = 0;
  for (size_t i = 0; i < sequence->ops.size(); ++i) {
    Op& op = *sequence->ops[i];
    try {
      current = ApplyOp(&op, sequence->gates[i], current);
    } catch (const FieldError& e) {
      throw SequenceError(OpLabel(i, op.Name()) + ": field '" + e.field() + "': " + e.what());
    }
    const std::string problem = current.Validate();
    if (!problem.empty()) throw SequenceError(OpLabel(i, op.Name()) + ": result invalid: " + problem);
    total_faces += static_cast<int64_t>(current.faces.size());
    if (static_cast<int64_t>(current.faces.size()) > kMaxOpFaces || total_faces > kMaxSequenceFaces) {
      throw SequenceError(OpLabel(i, op.Name()) + ": output too large: " + std::to_string(current.faces.size()) +
                          " faces (" + std::to_string(total_faces) + " over the steps so far; the limits are " +
                          std::to_string(kMaxOpFaces) + " and " + std::to_string(kMaxSequenceFaces) + ")");
    }
    steps.push_back(current);
  }
  return steps;
}

namespace {

// Helpers shared by every op's Blender code.
const char* kBlenderPreamble = R"PY(# Rebuilds an opgraph design sequence with Blender's own operators and modifiers.
# Usage: blender -b --factory-startup --python-exit-code 1 -P rebuild_blender.py -- OUT.obj
# Writes the evaluated mesh to OUT.obj in Blender's frame (+Z up, no axis conversion).
import os
import sys

import bmesh
import bpy
from mathutils import Euler, Matrix, Vector


def new_object(size):
    for o in list(bpy.data.objects):
        bpy.data.objects.remove(o, do_unlink=True)
    me = bpy.data.meshes.new('opgraph')
    bm = bmesh.new()
    bmesh.ops.create_cube(bm, size=size)
    bm.to_mesh(me)
    bm.free()
    obj = bpy.data.objects.new('opgraph', me)
    bpy.context.scene.collection.objects.link(obj)
    bpy.context.view_layer.objects.active = obj
    return obj


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


def export_obj(obj, path):
    dg = bpy.context.evaluated_depsgraph_get()
    me = obj.evaluated_get(dg).to_mesh()
    lines = ['# opgraph rebuild_blender.py, Blender %s' % bpy.app.version_string]
    lines += ['v %.9g %.9g %.9g' % tuple(v.co) for v in me.vertices]
    lines += ['f ' + ' '.join(str(i + 1) for i in p.vertices) for p in me.polygons]
    tmp = path + '.tmp'
    with open(tmp, 'w') as f:
        f.write('\n'.join(lines) + '\n')
    os.replace(tmp, path)


argv = sys.argv[sys.argv.index('--') + 1:] if '--' in sys.argv else []
if len(argv) != 1:
    sys.exit('usage: blender -b --factory-startup --python-exit-code 1 -P rebuild_blender.py -- OUT.obj')
)PY";

}  // namespace

std::string BlenderScript(const Sequence& sequence) {
  std::ostringstream script;
  script << kBlenderPreamble << kVertexSelectorPython << "\nkMinFaceShape = " << Py(kMinFaceShape) << "\n" << kFaceSelectorPython << "\nobj = new_object(" << Py(sequence.start_size) << ")\n";
  for (size_t i = 0; i < sequence.ops.size(); ++i) {
    const Op& op = *sequence.ops[i];
    script << "\n# " << i << ": " << op.Name() << "\n";
    if (sequence.gates[i] != 1.0) {
      throw SequenceError(OpLabel(i, op.Name()) + ": field 'gate': Blender export needs gate 1 (run the fitter's finalisation first)");
    }
    script << op.BlenderCode();
  }
  script << "\nexport_obj(obj, argv[0])\n";
  return script.str();
}

}  // namespace opgraph
