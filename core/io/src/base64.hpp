// Base64 (RFC 4648, with '=' padding), the text encoding of VTK XML "binary" data arrays.
#pragma once

#include <cstddef>
#include <string>

namespace styk::io {

// Appends the encoding of `size` bytes at `data` to `out`.
void base64_append(const void* data, std::size_t size, std::string& out);

}  // namespace styk::io
