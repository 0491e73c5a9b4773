#pragma once
// The service's bearer token: the secret a client shows ("Authorization: Bearer <token>") to
// write, and to read from another host. Kept in a file of mode 0600 beside the service.

#include <filesystem>
#include <string>
#include <string_view>

namespace ballsight {

/// The token in `file` (its first line), or a new random one written there with mode 0600 when
/// the file does not exist. Throws InputError naming the file when it cannot be read or written.
std::string read_or_create_token(const std::filesystem::path& file);

/// Whether the value of an Authorization header shows `token`, compared in a time that does not
/// depend on where the two differ.
bool shows_token(std::string_view authorization, const std::string& token);

}  // namespace ballsight
