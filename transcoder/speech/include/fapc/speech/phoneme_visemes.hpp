// eSpeak NG phoneme mnemonics to MPEG-4 visemes (docs/speech.md, "Phonemes to visemes").
#pragma once

#include <string_view>

namespace fapc::speech {

// The viseme (1..14) of one eSpeak NG phoneme in `language` ("en", "en-us", "fr", "de", ...: the
// part before '-' chooses the language's own entries, where a mnemonic means another sound there);
// 0 for a pause ('_...') or a sound without a mouth shape of its own (h, the glottal stop); -1 when
// the table has no entry even after dropping eSpeak's trailing variant marks (# - : ; / .).
int viseme_of_espeak_phoneme(std::string_view language, std::string_view mnemonic);

}  // namespace fapc::speech
