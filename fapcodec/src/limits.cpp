#include "fapc/codec/limits.hpp"

#include <cstdio>

#include "fapc/codec/codes.hpp"

namespace fapc {

const char* limit_option(Limit which) {
  switch (which) {
    case Limit::frames:
      return "--max-frames";
    case Limit::runs:
      return "--max-runs";
    case Limit::decompressed_bytes:
      return "--max-decompressed-bytes";
    case Limit::expansion:
      return "--max-expansion";
    case Limit::audio_samples:
      return "--max-audio-samples";
    case Limit::speech_text:
      return "--max-speech-text";
    case Limit::speech_seconds:
      return "--max-speech-seconds";
    case Limit::frame_pixels:
      return "--max-frame-pixels";
    case Limit::sheet_pixels:
      return "--max-sheet-pixels";
    case Limit::video_pixels:
      return "--max-video-pixels";
  }
  return "";
}

std::string limit_value(Limit which, const Limits& limits) {
  switch (which) {
    case Limit::frames:
      return std::to_string(limits.max_frames);
    case Limit::runs:
      return std::to_string(limits.max_runs);
    case Limit::decompressed_bytes:
      return std::to_string(limits.max_decompressed_bytes);
    case Limit::expansion:
    case Limit::speech_seconds: {
      char text[32];
      std::snprintf(text, sizeof text, "%g",
                    which == Limit::expansion ? limits.max_expansion : limits.max_speech_seconds);
      return text;
    }
    case Limit::audio_samples:
      return std::to_string(limits.max_audio_samples);
    case Limit::speech_text:
      return std::to_string(limits.max_speech_text_bytes);
    case Limit::frame_pixels:
      return std::to_string(limits.max_frame_pixels);
    case Limit::sheet_pixels:
      return std::to_string(limits.max_sheet_pixels);
    case Limit::video_pixels:
      return std::to_string(limits.max_video_pixels);
  }
  return "";
}

namespace {

// The error code of passing each limit (codes.def): a user raises each with its own option.
ErrorCode limit_code(Limit which) {
  switch (which) {
    case Limit::frames:
      return codes::limit::frames;
    case Limit::runs:
      return codes::limit::runs;
    case Limit::decompressed_bytes:
      return codes::limit::decompressed_bytes;
    case Limit::expansion:
      return codes::limit::expansion;
    case Limit::audio_samples:
      return codes::limit::audio_samples;
    case Limit::speech_text:
      return codes::limit::speech_text;
    case Limit::speech_seconds:
      return codes::limit::speech_seconds;
    case Limit::frame_pixels:
      return codes::limit::frame_pixels;
    case Limit::sheet_pixels:
      return codes::limit::sheet_pixels;
    case Limit::video_pixels:
      return codes::limit::video_pixels;
  }
  return codes::limit::frames;
}

const char* unit(Limit which) {
  switch (which) {
    case Limit::frames:
      return " frames";
    case Limit::runs:
      return " runs";
    case Limit::decompressed_bytes:
      return " bytes";
    case Limit::expansion:
      return " times the compressed size";
    case Limit::audio_samples:
      return " audio samples";
    case Limit::speech_text:
      return " bytes of speech text";
    case Limit::speech_seconds:
      return " seconds of speech";
    case Limit::frame_pixels:
    case Limit::sheet_pixels:
    case Limit::video_pixels:
      return " pixels";
  }
  return "";
}

}  // namespace

Diagnostic limit_error(Location where, const std::string& what, Limit which, const Limits& limits) {
  return make_error(limit_code(which), std::move(where),
                    what + ": more than the limit of " + limit_value(which, limits) + unit(which) + " (" +
                        limit_option(which) + " N raises it)");
}

}  // namespace fapc
