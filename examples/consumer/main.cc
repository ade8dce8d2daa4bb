// opgraph as a library, through its entry header <opgraph/opgraph.h>: reads a shape, builds a small
// design sequence with the typed builders (ops/builders.h), replays it and writes the run's
// outputs, then recovers a sequence for the shape with a short search.
//
//   opgraph_consumer SHAPE [OUT_DIR]   (e.g. examples/barrel.obj; OUT_DIR: as apply_sequence's)
#include <algorithm>
#include <exception>
#include <iostream>

#include <opgraph/opgraph.h>

#include "ops/builders.h"

int main(int argc, char** argv) {
  using namespace opgraph;
  if (argc < 2) {
    std::cerr << "usage: opgraph_consumer SHAPE [OUT_DIR]\n";
    return 2;
  }
  try {
    const api::Target target = api::Target::FromFile(argv[1]);
    const api::Mesh shape = target.shape();
    std::cout << "target: " << shape.vertices.rows() << " vertices, " << shape.faces.size() << " faces\n";

    // The default cube (2 units wide) fitted to the shape's box, an opening cut into its top
    // (+Y, the barrel's up), subdivided once.
    const Vec3d lo = shape.vertices.colwise().minCoeff().transpose();
    const Vec3d hi = shape.vertices.colwise().maxCoeff().transpose();
    const Vec3d half = (hi - lo) / 2;
    build::FaceTarget top;
    top.normals = {Vec3d::UnitY()};
    top.centers = {Vec3d((lo.x() + hi.x()) / 2, hi.y(), (lo.z() + hi.z()) / 2)};
    top.expect = 1;
    build::ExtrudeArgs opening;
    opening.faces = top;
    opening.height = -0.3 * half.y();
    const Json document = build::Document({
        build::GlobalScale(half),
        build::GlobalTranslate((lo + hi) / 2),
        build::Inset(top, 0.15 * std::min(half.x(), half.z())),
        build::Extrude(opening),
        build::Subdivision(1),
    });
    const std::string sequence_json = document.dump();

    const api::Mesh result = api::ApplySequence(sequence_json);
    std::cout << "sequence: " << document["operations"].size() << " operations\n";
    std::cout << "result: " << result.vertices.rows() << " vertices, " << result.faces.size() << " faces\n";
    if (argc > 2) {
      api::WriteOptions write;
      write.comment = "opgraph_consumer result";
      api::WriteOutputs(sequence_json, argv[2], write);
      std::cout << "wrote " << argv[2] << "\n";
    }

    api::RecoverOptions search;
    search.work_budget = 2000;  // a short search, a few seconds
    const api::RecoverResult recovered = api::RecoverSequence(target, search);
    std::cout << "recovered: " << recovered.num_ops << " operations, loss " << recovered.loss << "\n";
  } catch (const std::exception& e) {
    std::cerr << "opgraph_consumer: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
