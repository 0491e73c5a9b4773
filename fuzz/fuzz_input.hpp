#pragma once
// What every fuzz target of a file parser does: the input as the file's bytes, through the parser
// the command line uses; an InputError (a clear refusal naming the file) is the only way out
// allowed for bad input, anything else (another exception, a crash, a sanitizer report) is a
// finding.

#include <cstdint>
#include <string_view>

#include "ballsight/core/error.hpp"

namespace ballsight::fuzz {

template <class Parse>
int parse_or_refuse(const std::uint8_t* data, std::size_t size, Parse&& parse) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  try {
    parse(bytes);
  } catch (const InputError&) {
  }
  return 0;
}

}  // namespace ballsight::fuzz
