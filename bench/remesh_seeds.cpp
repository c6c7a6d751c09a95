#include "bench/remesh_seeds.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "bench/bench_options.h"
#include "bench/remesh_measure.h"
#include "bench/report_text.h"

namespace ff::bench {

namespace {

// One side's runs of one case, a value per seed that ran.
struct SeedRuns {
  std::vector<double> time, hausdorff, rounds;
  int valid = 0, ran = 0;
  void add(const Measured& m, bool ours) {
    if (!m.ok || !m.quality_error.empty()) return;
    ++ran;
    valid += m.invalid_panels() == 0 ? 1 : 0;
    time.push_back(m.total());
    hausdorff.push_back(m.num("hausdorff"));
    if (ours) rounds.push_back(m.num("panel_rounds"));
  }
};

double median(std::vector<double> v) {
  if (v.empty()) return NAN;
  std::sort(v.begin(), v.end());
  const size_t h = v.size() / 2;
  return v.size() % 2 == 1 ? v[h] : 0.5 * (v[h - 1] + v[h]);
}

double mean(const std::vector<double>& v) {
  if (v.empty()) return NAN;
  double sum = 0.0;
  for (double x : v) sum += x;
  return sum / static_cast<double>(v.size());
}

double largest(const std::vector<double>& v) { return v.empty() ? NAN : *std::max_element(v.begin(), v.end()); }

}  // namespace

void print_seed_table(const std::vector<RemeshCase>& cases, const std::string& meshes, const SeedRunOptions& options,
                      const std::string& exe, std::vector<std::string>& notes, int& failures) {
  if (options.seeds <= 0) return;
  std::printf("### Over seeds 1-%d\n\n", options.seeds);
  std::printf(
      "Each input at seeds 1-%d, both sides at each seed (CGAL's random seeding takes the seed too); time = the "
      "fastest of %d run%s per seed, read + clean + solve as above; Hausdorff from the first run.\n\n",
      options.seeds, options.repeat, options.repeat == 1 ? "" : "s");
  std::printf(
      "| input | n | valid ours / CGAL "
      "| time s median ours / CGAL | median ratio "
      "| time s mean ours / CGAL | mean ratio "
      "| time s worst ours / CGAL | worst ratio "
      "| Hausdorff median ours / CGAL | ours: panel rounds median (max) | ours: time s per seed |\n");
  std::printf("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|\n");
  std::fflush(stdout);
  int compared = 0, median_faster = 0, mean_faster = 0, worst_faster = 0, median_lower_hausdorff = 0;
  for (const RemeshCase& c : cases) {
    if (mesh_file_missing(meshes, c.file, c.label, notes)) continue;
    SeedRuns ours, cgal;
    std::string per_seed;
    for (int seed = 1; seed <= options.seeds; ++seed) {
      const auto s = static_cast<std::uint64_t>(seed);
      // A failed run of either side is named in the notes (only ours counts as a failure).
      const auto failed = [&](const Measured& m, const char* side) {
        if (m.ok && m.quality_error.empty()) return false;
        notes.push_back(c.label + " seed " + std::to_string(seed) + ": " + side +
                        " failed: " + (m.ok ? m.quality_error : m.error));
        return true;
      };
      const Measured a = measure(exe, "ours", c, meshes, s, options.repeat, options.subdivision_ratio);
      if (failed(a, "ours")) ++failures;
      ours.add(a, true);
      per_seed += (per_seed.empty() ? "" : " ") + (a.ok ? fmt("%.3f", a.total()) : std::string("failed"));
      if (!options.with_cgal) continue;
      const Measured b = measure(exe, "cgal", c, meshes, s, options.repeat, options.subdivision_ratio);
      failed(b, "CGAL");
      cgal.add(b, false);
    }
    const double m_ours = median(ours.time), m_cgal = median(cgal.time);
    const double a_ours = mean(ours.time), a_cgal = mean(cgal.time);
    const double w_ours = largest(ours.time), w_cgal = largest(cgal.time);
    if (ours.ran > 0 && cgal.ran > 0) {
      ++compared;
      median_faster += m_ours <= m_cgal ? 1 : 0;
      mean_faster += a_ours <= a_cgal ? 1 : 0;
      worst_faster += w_ours <= w_cgal ? 1 : 0;
      median_lower_hausdorff += median(ours.hausdorff) < median(cgal.hausdorff) ? 1 : 0;
    }
    const std::string cgal_valid = options.with_cgal ? std::to_string(cgal.valid) + "/" + std::to_string(cgal.ran) : "-";
    std::printf("| %s | %d | %s | %s | %s | %s | %s | %s | %s | %s | %s (%s) | %s |\n", c.label.c_str(), c.panels,
                pair_cell(std::to_string(ours.valid) + "/" + std::to_string(ours.ran), cgal_valid).c_str(),
                pair_cell(fmt("%.3f", m_ours), fmt("%.3f", m_cgal)).c_str(), fmt("%.2f", m_ours / m_cgal).c_str(),
                pair_cell(fmt("%.3f", a_ours), fmt("%.3f", a_cgal)).c_str(), fmt("%.2f", a_ours / a_cgal).c_str(),
                pair_cell(fmt("%.3f", w_ours), fmt("%.3f", w_cgal)).c_str(), fmt("%.2f", w_ours / w_cgal).c_str(),
                pair_cell(fmt("%.5f", median(ours.hausdorff)), fmt("%.5f", median(cgal.hausdorff))).c_str(),
                fmt("%.0f", median(ours.rounds)).c_str(), fmt("%.0f", largest(ours.rounds)).c_str(), per_seed.c_str());
    std::fflush(stdout);
  }
  if (compared > 0) {
    std::printf(
        "\nTarget whole process no slower than CGAL VSA (DESIGN.md 7), over seeds 1-%d: median no slower on %d of %d "
        "inputs; mean no slower on %d of %d; worst seed no slower on %d of %d.  \n",
        options.seeds, median_faster, compared, mean_faster, compared, worst_faster, compared);
    std::printf("Target Hausdorff lower than CGAL VSA (DESIGN.md 5), over seeds 1-%d: median lower on %d of %d inputs.\n\n",
                options.seeds, median_lower_hausdorff, compared);
  } else {
    std::printf("\n");
  }
}

}  // namespace ff::bench
