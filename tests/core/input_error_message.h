#pragma once
// The message of the ff::InputError a call throws, for tests that check bad input is refused
// with a line naming the problem.
#include <string>
#include <utility>

#include "core/util/error.h"

namespace ff::test {

// Runs `fn` (any callable taking no arguments) and returns the what() of the InputError it
// throws; `if_accepted` when it returns normally. Other exceptions pass through, so a wrong
// kind of error still fails the test.
template <class Fn>
std::string input_error_message(Fn&& fn, std::string if_accepted = "") {
  try {
    std::forward<Fn>(fn)();
  } catch (const InputError& e) {
    return e.what();
  }
  return if_accepted;
}

}  // namespace ff::test
