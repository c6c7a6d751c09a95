#pragma once
// What both benchmarks' Markdown reports are written with: number cells, the machine and
// load lines above the tables, and the notes and exit code at the end.
#include <string>
#include <vector>

namespace ff::bench {

// printf `format` of v, or "-" when v is not finite.
std::string fmt(const char* format, double v);

// A cell with both sides' values: "ours / cgal".
std::string pair_cell(const std::string& ours, const std::string& cgal);

// "CPU model, N cores; compiler; CGAL version" (or "without CGAL").
std::string machine_line();

// The 1, 5 and 15 minute load averages, "%.2f %.2f %.2f".
std::string load_average();

// Prints each note ("\nNote: ..."), then returns the exit code: 1, with "PROGRAM: N
// measurement(s) failed" on stderr, when failures > 0, else 0.
int finish_report(const char* program, const std::vector<std::string>& notes, int failures);

}  // namespace ff::bench
