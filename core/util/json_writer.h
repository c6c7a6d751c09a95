#pragma once
// A tiny streaming JSON writer for the summary and report files: objects, arrays, strings
// (escaped), numbers at full precision (non-finite numbers become null), booleans.
#include <cstdint>
#include <string>
#include <vector>

namespace ff {

class JsonWriter {
 public:
  JsonWriter& begin_object(const char* key = nullptr);
  JsonWriter& end_object();
  JsonWriter& begin_array(const char* key = nullptr);
  JsonWriter& end_array();
  JsonWriter& value(const char* key, double v);
  JsonWriter& value(const char* key, int v);
  JsonWriter& value(const char* key, std::int64_t v);
  JsonWriter& value(const char* key, std::uint64_t v);
  JsonWriter& value(const char* key, bool v);
  JsonWriter& value(const char* key, const std::string& v);
  JsonWriter& value(const char* key, const char* v) { return value(key, std::string(v)); }
  const std::string& str() const { return out_; }

 private:
  void prefix(const char* key);
  std::string out_;
  std::vector<bool> first_;  // per open container: nothing written yet
};

std::string json_escape(const std::string& s);

}  // namespace ff
