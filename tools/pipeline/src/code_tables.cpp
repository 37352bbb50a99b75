#include "fapc/pipeline/code_tables.hpp"

#include "fapc/audio_codec/codes.hpp"
#include "fapc/bml/codes.hpp"
#include "fapc/codec/codes.hpp"
#include "fapc/face/codes.hpp"
#include "fapc/fml/codes.hpp"
#include "fapc/head3d/codes.hpp"
#include "fapc/intent/codes.hpp"
#include "fapc/mpeg4/codes.hpp"
#include "fapc/pipeline/codes.hpp"
#include "fapc/smil/codes.hpp"
#include "fapc/speech/codes.hpp"
#include "fapc/timeline/codes.hpp"
#include "fapc/transcoder/codes.hpp"
#include "fapc/vocabulary/codes.hpp"
#include "fapc/xml/codes.hpp"
#include "fapc/xmto/codes.hpp"

namespace fapc::pipeline {

std::vector<CodeTable> code_tables() {
  return {{"fapc::codec", codes::codec_codes},
          {"fapc::timeline", codes::timeline_codes},
          {"fapc::transcoder", codes::transcoder_codes},
          {"fapc::speech", codes::speech_codes},
          {"fapc::audio_codec", codes::audio_codec_codes},
          {"fapc::face", codes::face_codes},
          {"fapc::head3d", codes::head3d_codes},
          {"fapc::vocabulary", codes::vocabulary_codes},
          {"fapc::xml", codes::xml_codes},
          {"fapc::mpeg4", codes::mpeg4_codes},
          {"fapc::fml", codes::fml_codes},
          {"fapc::xmto", codes::xmto_codes},
          {"fapc::bml", codes::bml_codes},
          {"fapc::intent", codes::intent_codes},
          {"fapc::smil", codes::smil_codes},
          {"fapc::pipeline", codes::pipeline_codes}};
}

}  // namespace fapc::pipeline
