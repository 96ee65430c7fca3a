// The command line's numbers: every option's text turned into a number the same way, and every
// refusal in the project's one form, "--option = text: reason" (an impetus::Error naming the
// option), whether the text is not a number, overflows a double, or is outside the option's range.
#pragma once

#include <cstdint>
#include <string>

namespace impetus::cli {

/// The number `text` spells (a leading '+' allowed), for the option `option` (as the user typed
/// it, e.g. "--steps"). Refuses text that is not a number and numbers beyond a double's range
/// (1e400 overflows, 1e-400 underflows), naming which.
[[nodiscard]] double parseNumber(const std::string& option, const std::string& text);

/// A whole number from lowest to highest for `option`; written as the user likes (1000, 1e3,
/// 1000.0). Anything else is refused with the range in the message.
[[nodiscard]] std::int64_t parseWholeNumber(const std::string& option, const std::string& text, std::int64_t lowest,
                                            std::int64_t highest);

} // namespace impetus::cli
