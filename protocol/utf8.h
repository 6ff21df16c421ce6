// UTF-8 well-formedness (RFC 3629): strings on the wire must be valid UTF-8 so that
// clients in other languages can decode them.
#pragma once

#include <string_view>

namespace cloudsvc::protocol {

// False for truncated sequences, overlong encodings, surrogates (U+D800..U+DFFF) and code
// points above U+10FFFF.
bool is_valid_utf8(std::string_view s);

}  // namespace cloudsvc::protocol
