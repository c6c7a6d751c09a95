#pragma once
// What a measurement run in a child process tells its parent on stdout: one line
// "result KEY=VALUE ...", and "error TEXT" when something failed. Written here, and read back
// by the parent.
#include <map>
#include <string>

namespace ff::bench {

// Builds the "result" line, values printed with %.9g.
class ResultLine {
 public:
  void add(const std::string& key, double v);
  void print() const;  // on stdout, flushed

 private:
  std::string text_;
};

// "error WHAT" on stdout, flushed.
void print_error(const std::string& what);

// The values of a child's "result" lines, by key.
struct ResultValues {
  std::map<std::string, double> values;

  double num(const std::string& key) const;  // NaN when the child did not say
  bool has(const std::string& key) const { return values.count(key) != 0; }
};

// Reads a child's stdout: every KEY=VALUE of its "result" lines into `into`; returns the text
// of its last "error" line (empty when there is none).
std::string read_result(const std::string& out, ResultValues& into);

}  // namespace ff::bench
