#include "base64.hpp"

namespace styk::io {

void base64_append(const void* data, std::size_t size, std::string& out) {
  static constexpr char kAlphabet[] =
      "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  const auto* bytes = static_cast<const unsigned char*>(data);
  out.reserve(out.size() + (size + 2) / 3 * 4);
  std::size_t i = 0;
  for (; i + 3 <= size; i += 3) {
    const unsigned triple = (bytes[i] << 16) | (bytes[i + 1] << 8) | bytes[i + 2];
    out += kAlphabet[(triple >> 18) & 63];
    out += kAlphabet[(triple >> 12) & 63];
    out += kAlphabet[(triple >> 6) & 63];
    out += kAlphabet[triple & 63];
  }
  const std::size_t rest = size - i;
  if (rest == 0) return;
  const unsigned triple = (bytes[i] << 16) | (rest == 2 ? bytes[i + 1] << 8 : 0);
  out += kAlphabet[(triple >> 18) & 63];
  out += kAlphabet[(triple >> 12) & 63];
  out += rest == 2 ? kAlphabet[(triple >> 6) & 63] : '=';
  out += '=';
}

}  // namespace styk::io
