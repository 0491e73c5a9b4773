#pragma once
// What OpenCV's ONNX importer does not check (4.6: fuzzing found it allocating what a corrupt
// file's sizes say, and reading a tensor's data beyond the file): every tensor of an ONNX model
// checked before OpenCV reads it. The file is walked as protobuf (the wire format, the fields of
// onnx.proto that hold tensors: the graph's initializers, nodes' attributes, subgraphs); each
// tensor's dims must be bounded and its data exactly as long as they say.

#include <string>
#include <string_view>

namespace ballsight {

/// The most elements a tensor of a model may hold (a ball verifier has some 10^5 weights).
inline constexpr long long kMaxOnnxTensorElements = 1LL << 26;

/// Throws InputError, naming `where`, when `bytes` are no well-formed ONNX protobuf or a tensor
/// in them is larger than kMaxOnnxTensorElements, of an unknown type, stored outside the file,
/// or holds other than its dims' worth of data.
void check_onnx_sizes(std::string_view bytes, const std::string& where);

}  // namespace ballsight
