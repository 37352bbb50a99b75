#include <cctype>

#include "fapc/transcoder/speech.hpp"

namespace fapc {

double estimated_speech_seconds(std::string_view text, double words_per_minute) {
  // Letters and digits: ASCII ones, and every non-ASCII character (its lead byte), as scripts
  // other than Latin have no ASCII letters at all.
  double letters = 0;
  for (const char c : text) {
    const auto u = static_cast<unsigned char>(c);
    if (std::isalnum(u) || u >= 0xC0) ++letters;
  }
  constexpr double kFastestLettersPerSecond = 24;  // at 175 words per minute
  const double per_second = kFastestLettersPerSecond * std::max(1.0, words_per_minute) / 175;
  return letters / per_second;
}

}  // namespace fapc
