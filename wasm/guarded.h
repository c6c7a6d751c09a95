#pragma once
// Status JSON and the guard every Session call runs under: nothing crosses into JavaScript
// as an exception (wasm/flatfacet.d.ts, Status).
#include <exception>
#include <new>
#include <string>

#include "core/mesh/clean.h"
#include "core/util/error.h"
#include "core/util/json_writer.h"

namespace ff::wasm {

inline std::string status_json(bool ok, const std::string& message) {
  JsonWriter j;
  j.begin_object().value("ok", ok).value("message", message).end_object();
  return j.str();
}

// Runs `f`, turning every exception into a Status JSON.
template <typename F>
std::string guarded(F&& f) {
  try {
    return f();
  } catch (const LargestPartError& e) {
    // Non-manifold edges or a far-off part: the page offers to open the largest part instead
    // (Session::set_repair).
    JsonWriter j;
    j.begin_object().value("ok", false).value("message", e.what());
    j.begin_object("largestPart").value("faces", e.largest_part_faces).value("of", e.total_faces).end_object();
    j.end_object();
    return j.str();
  } catch (const InputError& e) {
    return status_json(false, e.what());
  } catch (const std::bad_alloc&) {
    return status_json(false, "out of memory: the mesh or the panel count is too large for this browser tab");
  } catch (const std::exception& e) {
    return status_json(false, std::string("internal error: ") + e.what());
  } catch (...) {
    return status_json(false, "internal error");
  }
}

}  // namespace ff::wasm
