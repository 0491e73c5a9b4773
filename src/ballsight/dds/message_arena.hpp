#pragma once
// Storage for a message being built: the generated C structs point at strings and sequence
// buffers, which live here until the message is written (and the arena dropped).

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

namespace ballsight::dds {

class MessageArena {
 public:
  /// A NUL-terminated copy of `text` that lives as long as the arena.
  char* text(const std::string& text) {
    auto copy = std::make_shared<char[]>(text.size() + 1);
    text.copy(copy.get(), text.size());
    blocks_.push_back(copy);
    return copy.get();
  }
  /// `n` value-initialised (zeroed) elements that live as long as the arena.
  template <class T>
  T* array(std::size_t n) {
    auto block = std::make_shared<T[]>(n);
    blocks_.push_back(block);
    return block.get();
  }
  /// Gives the DDS sequence `sequence` `n` zeroed elements of the arena's.
  template <class Sequence>
  auto* fill(Sequence& sequence, std::size_t n) {
    sequence._buffer = array<std::remove_pointer_t<decltype(sequence._buffer)>>(n);
    sequence._length = sequence._maximum = static_cast<std::uint32_t>(n);
    sequence._release = false;
    return sequence._buffer;
  }

 private:
  std::vector<std::shared_ptr<void>> blocks_;
};

}  // namespace ballsight::dds
