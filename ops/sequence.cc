#include "ops/sequence.h"

#include "core/printable.h"

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
  if (document.contains("name")) sequence.name = document["name"].get<std::string>();
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
        if (it.key() != "op" && it.key() != "params" && it.key() != "gate" && it.key() != "pinned") {
          throw FieldError(Printable(it.key()), "unknown field");
        }
      }
      const Json params = entry.contains("params") ? entry["params"] : Json::object();
      sequence.ops.push_back(CreateOp(name, params));
      sequence.gates.push_back(entry.contains("gate") ? CheckedNumber(entry["gate"], "gate", 0, 1) : 1.0);
      if (entry.contains("pinned") && !entry["pinned"].is_boolean()) throw FieldError("pinned", "must be true or false");
      sequence.pinned.push_back(entry.value("pinned", false));
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
  } catch (const Json::exception& e) {  // a syntax error, or a number beyond double (1e400)
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
    if (sequence.IsPinned(i)) entry["pinned"] = true;
    ops.push_back(entry);
  }
  Json document = {{"format", "opgraph-sequence"}, {"version", kSequenceFormatVersion}};
  if (!sequence.name.empty()) document["name"] = sequence.name;
  document["start"] = {{"primitive", "cube"}, {"size", sequence.start_size}};
  document["operations"] = ops;
  return document;
}

Mesh ApplyOp(Op* op, double gate, const Mesh& input) {
  op->Prepare(input);
  Mesh next;
  op->Evaluate(op->params().data(), gate, input.vertices, &next.vertices);
  next.faces = op->OutputFaces(gate);
  return next;
}

std::vector<Mesh> EvaluateSequence(Sequence* sequence) {
  const int64_t max_faces = sequence->max_faces;
  const int64_t max_total_faces = 4 * max_faces;
  auto too_large = [&](size_t i, const Op& op, const std::string& what) {
    return SequenceError(OpLabel(i, op.Name()) + ": output too large: " + what + " --max-faces " +
                         std::to_string(max_faces));
  };
  std::vector<Mesh> steps;
  Mesh current = sequence->StartMesh();
  int64_t total_faces = 0;
  for (size_t i = 0; i < sequence->ops.size(); ++i) {
    Op& op = *sequence->ops[i];
    // Refused before the op allocates, where it and the ops after it know their sizes
    // beforehand (20 Subdivisions fail at once, not after 9 of them).
    int64_t faces_ahead = static_cast<int64_t>(current.faces.size()), corners_ahead = 0;
    for (const Polygon& face : current.faces) corners_ahead += static_cast<int64_t>(face.size());
    for (size_t j = i; j < sequence->ops.size() && sequence->ops[j]->PredictOutputFaces(&faces_ahead, &corners_ahead);
         ++j) {
      if (faces_ahead > max_faces) {
        throw too_large(j, *sequence->ops[j], "would make " + std::to_string(faces_ahead) + " faces, above");
      }
    }
    try {
      op.set_max_output_faces(max_faces);
      current = ApplyOp(&op, sequence->gates[i], current);
    } catch (const FieldError& e) {
      throw SequenceError(OpLabel(i, op.Name()) + ": field '" + e.field() + "': " + e.what());
    }
    const std::string problem = current.Validate();
    if (!problem.empty()) throw SequenceError(OpLabel(i, op.Name()) + ": result invalid: " + problem);
    const int64_t faces = static_cast<int64_t>(current.faces.size());
    total_faces += faces;
    if (faces > max_faces) throw too_large(i, op, std::to_string(faces) + " faces, above");
    if (total_faces > max_total_faces) {
      throw too_large(i, op, std::to_string(total_faces) + " faces over the steps so far, above 4 times");
    }
    steps.push_back(current);
  }
  return steps;
}

}  // namespace opgraph
