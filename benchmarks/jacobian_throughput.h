// The Jacobian throughput part of fit_benchmark: for a ~2,000-vertex program with 10,000
// point-to-plane samples, program Jacobians, residual Jacobians, and the same through Ceres'
// Problem::Evaluate, each for two seconds; prints a Markdown table.
#pragma once

namespace opgraph {

void PrintJacobianThroughput();

}  // namespace opgraph
