#pragma once
// A small JSON reader for parameter objects that cross from the browser (and may come from a
// hostile share link): objects, arrays, strings, numbers, booleans, null, with JSON's grammar
// checked strictly (no NaN, hex, leading zeros, trailing commas or garbage). Nesting and size
// are bounded; any error throws InputError naming the offset. Strings are kept as bytes (not
// checked as UTF-8): callers compare them with ASCII words.
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace ff {

struct JsonValue {
  enum class Type { Null, Boolean, Number, String, Array, Object };
  Type type = Type::Null;
  bool boolean = false;
  double number = 0.0;
  std::string string;
  std::vector<JsonValue> array;
  std::vector<std::pair<std::string, JsonValue>> object;  // in document order

  // The member named `key`, or nullptr (also for non-objects). The last one wins on repeats.
  const JsonValue* find(std::string_view key) const;
};

// Throws InputError for syntax errors, nesting deeper than max_depth, text longer than
// max_bytes, or trailing garbage.
JsonValue parse_json(std::string_view text, int max_depth = 16, size_t max_bytes = 1 << 20);

}  // namespace ff
