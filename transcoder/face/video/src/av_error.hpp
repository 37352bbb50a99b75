// libav's words for one of its error codes, for the messages of fapc's errors.
#pragma once

extern "C" {
#include <libavutil/error.h>
}

#include <string>

namespace fapc::face {

inline std::string av_message(int code) {
  char text[AV_ERROR_MAX_STRING_SIZE] = {};
  av_strerror(code, text, sizeof text);
  return text;
}

}  // namespace fapc::face
