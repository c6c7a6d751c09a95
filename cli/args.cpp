#include "cli/args.h"

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace ff::cli {

namespace {

// A token as a message shows it: bytes that are not printable ASCII as \xNN (a binary file given
// as numbers), and no longer than 40 characters.
std::string printable(const std::string& text) {
  std::string out;
  for (const char c : text.substr(0, 40)) {
    const auto byte = static_cast<unsigned char>(c);
    if (byte >= 0x20 && byte < 0x7f) {
      out += c;
    } else {
      static const char* const hex = "0123456789abcdef";
      out += "\\x";
      out += hex[byte >> 4];
      out += hex[byte & 15];
    }
  }
  return text.size() > 40 ? out + "..." : out;
}

}  // namespace

double parse_double(const std::string& text, const std::string& what) {
  if (text.empty()) throw UsageError(what + ": expected a number, got nothing");
  char* end = nullptr;
  errno = 0;
  const double v = std::strtod(text.c_str(), &end);
  if (end != text.c_str() + text.size() || !std::isfinite(v))
    throw UsageError(what + ": '" + printable(text) + "' is not a finite number");
  if (errno == ERANGE) throw UsageError(what + ": '" + printable(text) + "' is too close to 0 to hold in a double");
  return v;
}

std::string Args::get(const std::string& name, const std::string& fallback) const {
  const auto it = options.find(name);
  return it == options.end() ? fallback : it->second;
}

long long parse_int(const std::string& text, const std::string& what, long long lo, long long hi) {
  long long v = 0;
  const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (ec != std::errc() || ptr != text.data() + text.size())
    throw UsageError(what + ": '" + text + "' is not a whole number");
  if (v < lo || v > hi)
    throw UsageError(what + ": " + text + " is out of range [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
  return v;
}

long long Args::get_int(const std::string& name, long long fallback, long long lo, long long hi) const {
  return has(name) ? parse_int(options.at(name), "--" + name, lo, hi) : fallback;
}

Args parse_args(const std::vector<std::string>& argv, const std::set<std::string>& with_value,
                const std::set<std::string>& switches) {
  Args args;
  for (size_t i = 0; i < argv.size(); ++i) {
    const std::string& a = argv[i];
    if (a.size() > 2 && a.compare(0, 2, "--") == 0) {
      std::string name = a.substr(2), value;
      const size_t eq = name.find('=');
      const bool inline_value = eq != std::string::npos;
      if (inline_value) {
        value = name.substr(eq + 1);
        name = name.substr(0, eq);
      }
      if (switches.count(name)) {
        if (inline_value) throw UsageError("--" + name + " takes no value");
        args.flags.insert(name);
      } else if (with_value.count(name)) {
        if (!inline_value) {
          if (i + 1 >= argv.size()) throw UsageError("--" + name + " needs a value");
          value = argv[++i];
        }
        if (args.options.count(name)) throw UsageError("--" + name + " given twice");
        args.options[name] = value;
      } else {
        throw UsageError("unknown option --" + name);
      }
    } else {
      args.positional.push_back(a);
    }
  }
  return args;
}

MetricWeights parse_weights(const std::string& text) {
  MetricWeights w;
  std::stringstream ss(text);
  std::string item;
  std::set<std::string> given;  // a term given twice was taken silently, the last value winning
  while (std::getline(ss, item, ',')) {
    const size_t eq = item.find('=');
    if (eq == std::string::npos) throw UsageError("--weights: expected name=value, got '" + item + "'");
    const std::string name = item.substr(0, eq);
    if (!given.insert(name).second) throw UsageError("--weights: " + name + " is given twice");
    const double v = parse_double(item.substr(eq + 1), "--weights " + name);
    if (v < 0.0) throw UsageError("--weights " + name + ": weights must be >= 0");
    if (name == "euclidean")
      w.euclidean = v;
    else if (name == "l2")
      w.l2 = v;
    else if (name == "l21")
      w.l21 = v;
    else if (name == "density")
      w.density = v;
    else if (name == "boundary")
      w.boundary = v;
    else
      throw UsageError("--weights: unknown term '" + name + "' (use euclidean, l2, l21, density, boundary)");
  }
  return w;
}

const std::set<std::string>& subdivision_option_names() {
  static const std::set<std::string> names = {"subdivide", "crease-angle"};
  return names;
}

SubdivisionRequest parse_subdivision(const Args& args) {
  SubdivisionRequest r;
  // Each level multiplies the faces by 4; the core refuses results above its triangle cap.
  r.levels = static_cast<int>(args.get_int("subdivide", 0, 0, 16));
  if (args.has("crease-angle")) {
    if (r.levels == 0) throw UsageError("--crease-angle needs --subdivide N (N >= 1)");
    r.crease_angle_deg = parse_double(args.get("crease-angle"), "--crease-angle");
    if (!(r.crease_angle_deg >= 0.0 && r.crease_angle_deg <= 180.0))
      throw UsageError("--crease-angle: expected degrees between 0 and 180, got '" + args.get("crease-angle") + "'");
  }
  return r;
}

std::vector<double> read_numbers_file(const std::string& path, const std::string& what) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw UsageError(what + ": cannot open '" + path + "'");
  std::vector<double> values;
  std::string line;
  int line_no = 0;
  while (std::getline(in, line)) {
    ++line_no;
    const size_t hash = line.find('#');
    if (hash != std::string::npos) line.resize(hash);
    for (char& c : line) {
      if (c == ',' || c == '\t' || c == '\r' || c == ';') c = ' ';
    }
    std::stringstream ss(line);
    std::string token;
    while (ss >> token) {
      values.push_back(parse_double(token, what + " '" + path + "' line " + std::to_string(line_no)));
    }
  }
  if (values.empty()) throw UsageError(what + ": '" + path + "' holds no numbers");
  return values;
}

}  // namespace ff::cli
