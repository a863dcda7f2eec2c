// UTF-8 in and out: APL characters are one code point each, and one column on the screen.
#pragma once

#include <string>
#include <string_view>

namespace igds::apl {

// The code points of a UTF-8 text; a malformed byte becomes U+FFFD (never a valid APL character).
std::u32string decode_utf8(std::string_view text);
std::string encode_utf8(std::u32string_view text);
void append_utf8(std::string& out, char32_t c);

}  // namespace igds::apl
