// The cost of a run's ParaView frame: one wake sheet written as a .vtp, as the run writes it
// every `vtk_every` steps (docs/output_files.md, "Writing cost"). The sheet is the size of the
// 16-wingbeat rigid hover's wake at its end: 4400 points, 3990 quadrilateral rings, a point
// field and two cell fields, nine numbers of field data.
#include <benchmark/benchmark.h>

#include <filesystem>
#include <string>

#include "pipeline/io/vtk_writers.hpp"

namespace {

flapsim::io::PolyDataMesh wake_sheet(int rows, int columns) {
  flapsim::io::PolyDataMesh mesh;
  const int nodes_across = columns + 1;
  mesh.points.resize(3, static_cast<long>(rows + 1) * nodes_across);
  for (int r = 0; r <= rows; ++r)
    for (int c = 0; c < nodes_across; ++c)
      mesh.points.col(r * nodes_across + c) << 1e-3 * r, 6e-3 * c, 1e-4 * ((r * 7 + c * 3) % 11);
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < columns; ++c) {
      const int a = r * nodes_across + c;
      mesh.polygons.push_back({a, a + 1, a + 1 + nodes_across, a + nodes_across});
    }
  Eigen::VectorXd age = Eigen::VectorXd::LinSpaced(mesh.points.cols(), 0.0, 0.55);
  mesh.point_data.add_scalar("age_s", age);
  const auto cells = static_cast<long>(mesh.polygons.size());
  mesh.cell_data.add_scalar("circulation_m2_s", Eigen::VectorXd::LinSpaced(cells, -0.07, 0.07));
  mesh.cell_data.add_scalar("age_s", Eigen::VectorXd::LinSpaced(cells, 0.0007, 0.55));
  for (const char* name : {"step", "t_over_T", "lift_N", "CL", "drag_N", "CD", "power_W", "drive_power_W"})
    mesh.field_data.add_number(name, 1.0);
  mesh.time = 0.5;
  return mesh;
}

void BM_WakeFrame(benchmark::State& state) {
  const auto mesh = wake_sheet(399, 10);  // 400 x 11 = 4400 points, 3990 rings
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "flapsim_bench_vtk_output";
  std::filesystem::create_directories(dir);
  int frame = 0;
  for (auto _ : state)
    flapsim::io::write_vtp(dir / ("wake_" + std::to_string(frame++ % 64) + ".vtp"), mesh,
                           flapsim::io::Flush::deferred);
  state.SetBytesProcessed(state.iterations() *
                          static_cast<long>(std::filesystem::file_size(dir / "wake_0.vtp")));
  std::filesystem::remove_all(dir);
}
BENCHMARK(BM_WakeFrame)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
