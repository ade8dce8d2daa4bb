// opgraph as a library: reads a shape, builds a small design sequence with the typed builders
// (ops/builders.h), replays it, scores it against the shape and writes the run's outputs.
//
//   opgraph_consumer SHAPE [OUT_DIR]   (e.g. examples/barrel.obj; OUT_DIR: as apply_sequence's)
#include <algorithm>
#include <exception>
#include <iostream>
#include <memory>

#include "core/metrics.h"
#include "io/sequence_outputs.h"
#include "ops/builders.h"
#include "solver/target.h"

int main(int argc, char** argv) {
  using namespace opgraph;
  if (argc < 2) {
    std::cerr << "usage: opgraph_consumer SHAPE [OUT_DIR]\n";
    return 2;
  }
  try {
    const std::unique_ptr<Target> target = LoadTarget(argv[1], TargetOptions());
    const Mesh& shape = target->shape();
    std::cout << "target: " << shape.NumVertices() << " vertices, " << shape.NumFaces() << " faces\n";

    // The default cube (2 units wide) fitted to the shape's box, an opening cut into its top
    // (+Y, the barrel's up), subdivided once.
    Vec3d lo = shape.vertices[0], hi = shape.vertices[0];
    for (const Vec3d& p : shape.vertices) {
      lo = lo.cwiseMin(p);
      hi = hi.cwiseMax(p);
    }
    const Vec3d half = (hi - lo) / 2;
    build::FaceTarget top;
    top.normals = {Vec3d::UnitY()};
    top.centers = {Vec3d((lo.x() + hi.x()) / 2, hi.y(), (lo.z() + hi.z()) / 2)};
    top.expect = 1;
    build::ExtrudeArgs opening;
    opening.faces = top;
    opening.height = -0.3 * half.y();
    Sequence sequence = ParseSequence(build::Document({
        build::GlobalScale(half),
        build::GlobalTranslate((lo + hi) / 2),
        build::Inset(top, 0.15 * std::min(half.x(), half.z())),
        build::Extrude(opening),
        build::Subdivision(1),
    }));

    const SequenceOutputs outputs = RenderSequenceOutputs(&sequence);
    std::cout << "sequence: " << outputs.steps.size() << " operations\n";
    std::cout << "result: " << outputs.result.NumVertices() << " vertices, " << outputs.result.NumFaces()
              << " faces\n";
    const ShapeMetrics metrics = ComputeShapeMetrics(outputs.result, shape);
    std::cout << "F1 at 0.01 of the target's box: " << metrics.f1_001 << "\n";
    if (argc > 2) {
      WriteSequenceOutputs(outputs, argv[2], /*write_steps=*/true, "opgraph_consumer result");
      std::cout << "wrote " << argv[2] << "\n";
    }
  } catch (const std::exception& e) {
    std::cerr << "opgraph_consumer: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
