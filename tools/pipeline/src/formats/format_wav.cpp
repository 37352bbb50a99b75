// .wav as an output: the input's voice (spoken FML talk text, or a recording a script names) as
// mono 16-bit PCM, sample 0 at the face's time 0 (docs/speech.md).
#include "fapc/pipeline/codes.hpp"
#include "fapc/pipeline/registry.hpp"
#include "fapc/transcoder/wav.hpp"

namespace fapc::pipeline::builtin {

namespace {

Result<std::string> write_wav(const Loaded& loaded, const std::string& path, const ConvertOptions& options) {
  if (!loaded.audio || loaded.audio->samples.empty()) {
    return make_error(codes::output::no_audio, Location::whole_file(loaded.named(path)),
                      "this input has no audio to write to " + path +
                          " (audio comes from FML talk text, or an XMT-Omega audio element with a WAV file)");
  }
  // The file starts at the face's time 0: a voice that starts late is preceded by silence, which
  // the file holds sample by sample (an .mp4 whose audio edit list waits a day asks for 86,400 s).
  const AudioTrack& audio = *loaded.audio;
  const double samples = std::max(0.0, audio.start) * audio.sample_rate + static_cast<double>(audio.samples.size());
  if (samples > static_cast<double>(options.limits.max_audio_samples)) {
    return limit_error(Location::whole_file(loaded.named(path)),
                       "the .wav from time 0 to the voice's end (it starts at " + std::to_string(audio.start) +
                           " s) would hold " + std::to_string(static_cast<std::int64_t>(samples)) + " samples",
                       Limit::audio_samples, options.limits);
  }
  return wav_bytes(audio);
}

}  // namespace

OutputFormat wav_output() {
  OutputFormat format{"wav", {".wav"}, write_wav, /*uses_curves=*/false, /*uses_frames=*/false};
  format.uses_audio = true;
  return format;
}

}  // namespace fapc::pipeline::builtin
