// Talk text shaped so that eSpeak NG 1.51 can take it (docs/speech.md, "Hostile text"): the
// engine has fixed-size buffers that some text overruns (it then aborts or crashes the whole
// process), and its cost grows with the length of one call. What fapc hands it is therefore
// cut into bounded pieces, spoken one after the other, and shaped to avoid the faults found.
// Engine-independent: plain text in, plain text out, so it is tested without the engine.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace fapc::speech {

// The longest run of non-space bytes handed to the engine as one word. A word carrying many
// stacked suffixes (English "s's's'...", 70 of them) overflows the engine's 200-byte phoneme
// buffer of one word and aborts ("buffer overflow detected"); 64 stacked ones still pass, so a
// word of at most 48 bytes (24 of them) keeps a margin. Longer runs are broken with a space at a
// character boundary: no honest word is that long (German compounds reach about 40 letters).
inline constexpr std::size_t kMaxWordBytes = 48;

// The most bytes of text handed to the engine in one call; a piece ends at a sentence's end
// where there is one, else at a space, else at a character boundary.
inline constexpr std::size_t kMaxPieceBytes = 1000;

// The text with its hostile shapes neutralised: runs of one punctuation character (other than
// '.') become one ("---" before a Devanagari word makes the Hindi voice read before the start of
// its phoneme list and crash), runs of '.' are cut to three, control characters become spaces,
// and words longer than kMaxWordBytes are broken. Characters Unicode does not assign (and bytes
// that are not UTF-8) become spaces: an unassigned Armenian code point before Arabic punctuation
// (U+058C U+060C) makes the engine switch languages and read a dictionary it has just freed.

std::string speakable_text(std::string_view text);

// speakable_text(text) cut into pieces of at most kMaxPieceBytes, none empty or blank.
std::vector<std::string> speakable_pieces(std::string_view text);

}  // namespace fapc::speech
