// .wav as an output: the input's voice (spoken FML talk text, or a recording a script names) as
// mono 16-bit PCM, sample 0 at the face's time 0 (docs/speech.md).
#include "fapc/transcoder/wav.hpp"
#include "formats.hpp"

namespace fapc::pipeline::builtin {

namespace {

Result<std::string> write_wav(const Loaded& loaded, const std::string& path, const ConvertOptions&) {
  if (!loaded.audio || loaded.audio->samples.empty()) {
    return make_error(ErrorKind::unsupported, Location{loaded.named(path), 0, 0, -1},
                      "this input has no audio to write to " + path +
                          " (audio comes from FML talk text, or an XMT-Omega audio element with a WAV file)");
  }
  return wav_bytes(*loaded.audio);
}

}  // namespace

OutputFormat wav_output() {
  OutputFormat format{"wav", {".wav"}, write_wav, /*uses_curves=*/false, /*uses_frames=*/false};
  format.uses_audio = true;
  return format;
}

}  // namespace fapc::pipeline::builtin
