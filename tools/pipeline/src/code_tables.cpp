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
#include "fapc/transcoder/codes.hpp"
#include "fapc/vocabulary/codes.hpp"
#include "fapc/xml/codes.hpp"
#include "fapc/xmto/codes.hpp"

namespace fapc::pipeline {

std::vector<CodeTable> code_tables() {
  return {{"codec", codes::codec_codes},           {"transcoder", codes::transcoder_codes},
          {"speech", codes::speech_codes},         {"audio_codec", codes::audio_codec_codes},
          {"face", codes::face_codes},             {"head3d", codes::head3d_codes},
          {"vocabulary", codes::vocabulary_codes}, {"xml", codes::xml_codes},
          {"mpeg4", codes::mpeg4_codes},           {"fml", codes::fml_codes},
          {"xmto", codes::xmto_codes},             {"bml", codes::bml_codes},
          {"intent", codes::intent_codes},         {"smil", codes::smil_codes},
          {"pipeline", codes::pipeline_codes}};
}

}  // namespace fapc::pipeline
