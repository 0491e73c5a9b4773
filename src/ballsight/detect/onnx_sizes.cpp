#include "ballsight/detect/onnx_sizes.hpp"

#include <cstdint>
#include <optional>
#include <vector>

#include "ballsight/core/error.hpp"

namespace ballsight {
namespace {

// Protobuf's wire types (protobuf.dev, "Encoding").
enum Wire : std::uint32_t { varint = 0, fixed64 = 1, length = 2, fixed32 = 5 };

// Subgraphs (an If's branches, a Loop's body) nest no deeper than this.
constexpr int kMaxDepth = 16;

class WireReader {
 public:
  WireReader(std::string_view bytes, const std::string& where) : in_(bytes), where_(where) {}

  bool done() const { return in_.empty(); }

  std::uint64_t read_varint() {
    std::uint64_t value = 0;
    for (int shift = 0; shift < 64; shift += 7) {
      require(!in_.empty(), where_, "ends inside a number (no ONNX model)");
      const auto byte = static_cast<std::uint8_t>(in_.front());
      in_.remove_prefix(1);
      value |= static_cast<std::uint64_t>(byte & 0x7f) << shift;
      if (!(byte & 0x80)) return value;
    }
    throw InputError(where_ + ": holds a number of more than 64 bits (no ONNX model)");
  }

  // The next field's number and wire type.
  std::pair<std::uint64_t, std::uint32_t> read_tag() {
    const std::uint64_t tag = read_varint();
    return {tag >> 3, static_cast<std::uint32_t>(tag & 7)};
  }

  std::string_view read_bytes() {
    const std::uint64_t n = read_varint();
    require(n <= in_.size(), where_, "holds a field longer than the file (no ONNX model)");
    const std::string_view out = in_.substr(0, n);
    in_.remove_prefix(n);
    return out;
  }

  void skip(std::uint32_t wire) {
    switch (wire) {
      case varint:
        read_varint();
        return;
      case fixed64:
        take(8);
        return;
      case length:
        read_bytes();
        return;
      case fixed32:
        take(4);
        return;
      default:
        throw InputError(where_ + ": holds a field of an unknown wire type (no ONNX model)");
    }
  }

 private:
  void take(std::size_t n) {
    require(n <= in_.size(), where_, "ends inside a field (no ONNX model)");
    in_.remove_prefix(n);
  }

  std::string_view in_;
  const std::string& where_;
};

// Bytes per element of onnx.proto's TensorProto.DataType, nullopt for an unknown one (0 for
// strings, whose length is their own).
std::optional<long long> element_bytes(std::uint64_t type) {
  switch (type) {
    case 2:
    case 3:
    case 9:  // uint8, int8, bool
      return 1;
    case 4:
    case 5:
    case 10:
    case 16:  // uint16, int16, float16, bfloat16
      return 2;
    case 1:
    case 6:
    case 12:  // float, int32, uint32
      return 4;
    case 7:
    case 11:
    case 13:
    case 14:  // int64, double, uint64, complex64
      return 8;
    case 15:  // complex128
      return 16;
    case 8:  // string
      return 0;
    default:
      return std::nullopt;
  }
}

class OnnxWalk {
 public:
  explicit OnnxWalk(const std::string& where) : where_(where) {}

  void model(std::string_view bytes) {
    messages(bytes, [&](std::uint64_t field, std::string_view message) {
      if (field == 7) graph(message, 0);  // ModelProto.graph
    });
  }

 private:
  // Calls visit(field, bytes) for each length-delimited field of a message (the nested messages
  // among them), skipping the others.
  template <typename Visit>
  void messages(std::string_view bytes, Visit visit) const {
    WireReader in(bytes, where_);
    while (!in.done()) {
      const auto [field, wire] = in.read_tag();
      if (wire == length)
        visit(field, in.read_bytes());
      else
        in.skip(wire);
    }
  }

  void graph(std::string_view bytes, int depth) {
    require(depth <= kMaxDepth, where_, "nests its graphs too deep");
    messages(bytes, [&](std::uint64_t field, std::string_view message) {
      if (field == 1) node(message, depth);     // GraphProto.node
      if (field == 5) tensor(message);          // GraphProto.initializer
      if (field == 15) sparse_tensor(message);  // GraphProto.sparse_initializer
    });
  }

  void node(std::string_view bytes, int depth) {
    messages(bytes, [&](std::uint64_t field, std::string_view message) {
      if (field == 5) attribute(message, depth);  // NodeProto.attribute
    });
  }

  void attribute(std::string_view bytes, int depth) {
    messages(bytes, [&](std::uint64_t field, std::string_view message) {
      if (field == 5 || field == 10) tensor(message);            // AttributeProto.t, .tensors
      if (field == 6 || field == 11) graph(message, depth + 1);  // AttributeProto.g, .graphs
      if (field == 22 || field == 23) sparse_tensor(message);    // .sparse_tensor(s)
    });
  }

  void sparse_tensor(std::string_view bytes) {
    messages(bytes, [&](std::uint64_t field, std::string_view message) {
      if (field == 1 || field == 2) tensor(message);  // SparseTensorProto.values, .indices
    });
  }

  // Counts the elements of a repeated scalar field, packed (length) or one at a time.
  static long long count(WireReader& in, std::uint32_t wire, int fixed_bytes) {
    if (wire != length) {
      in.skip(wire);
      return 1;
    }
    const std::string_view packed = in.read_bytes();
    if (fixed_bytes > 0) return static_cast<long long>(packed.size()) / fixed_bytes;
    long long n = 0;
    for (const char c : packed) n += (static_cast<std::uint8_t>(c) & 0x80) == 0;
    return n;
  }

  void tensor(std::string_view bytes) {
    WireReader in(bytes, where_);
    std::vector<std::uint64_t> dims;
    std::uint64_t type = 0;
    std::optional<long long> raw_bytes;
    long long typed = 0;  // elements in the typed data fields
    bool external = false;
    while (!in.done()) {
      const auto [field, wire] = in.read_tag();
      switch (field) {
        case 1:  // dims: int64, packed or not
          if (wire == length) {
            WireReader packed(in.read_bytes(), where_);
            while (!packed.done()) dims.push_back(packed.read_varint());
          } else {
            require(wire == varint, where_, "holds a tensor's dims of a wrong type");
            dims.push_back(in.read_varint());
          }
          break;
        case 2:  // data_type
          require(wire == varint, where_, "holds a tensor's data type of a wrong type");
          type = in.read_varint();
          break;
        case 9:  // raw_data
          require(wire == length, where_, "holds a tensor's raw data of a wrong type");
          raw_bytes = static_cast<long long>(in.read_bytes().size());
          break;
        case 4:  // float_data: fixed32
          typed += count(in, wire, 4);
          break;
        case 10:  // double_data: fixed64
          typed += count(in, wire, 8);
          break;
        case 5:   // int32_data (and the narrower types): varints
        case 7:   // int64_data
        case 11:  // uint64_data
          typed += count(in, wire, 0);
          break;
        case 6:  // string_data: one string each
          in.skip(wire);
          ++typed;
          break;
        case 13:
        case 14:  // external_data, data_location
          external = external || field == 13;
          in.skip(wire);
          break;
        default:
          in.skip(wire);
      }
    }
    require(!external, where_, "keeps a tensor's data outside the file");
    const std::string too_large =
        "holds a tensor of more than " + std::to_string(kMaxOnnxTensorElements) + " elements";
    long long elements = 1;
    for (const std::uint64_t d : dims) {
      // Each dim is bounded first, so that the product cannot overflow.
      require(d <= static_cast<std::uint64_t>(kMaxOnnxTensorElements), where_, too_large);
      elements *= static_cast<long long>(d);
      require(elements <= kMaxOnnxTensorElements, where_, too_large);
    }
    const std::optional<long long> size = element_bytes(type);
    require(size.has_value(), where_, "holds a tensor of an unknown data type");
    if (raw_bytes) {
      require(*size > 0 && *raw_bytes == elements * *size, where_,
              "holds a tensor whose raw data is not as long as its dims say");
    } else {
      require(typed == elements, where_,
              "holds a tensor whose data is not as long as its dims say");
    }
  }

  const std::string& where_;
};

}  // namespace

void check_onnx_sizes(std::string_view bytes, const std::string& where) {
  require(!bytes.empty(), where, "is empty (no ONNX model)");
  OnnxWalk(where).model(bytes);
}

}  // namespace ballsight
