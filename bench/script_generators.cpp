// The generated scripts of script_generators.hpp. Each block is one "utterance": a parallel group
// of kElementsPerBlock elements lasting 0.8 s, its numbers drawn from a fixed-seed generator so
// that blocks differ (no two neighbours share every curve) and runs repeat exactly.
#include "script_generators.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>

namespace fapc::bench {
namespace {

constexpr std::size_t kElementsPerBlock = 8;

// splitmix64: small, fast, and the same on every platform.
class Numbers {
 public:
  explicit Numbers(std::uint64_t seed) : state_(seed) {}
  // A value in [low, high) on a grid of 1/100, so the text stays short.
  double between(double low, double high) {
    const double u = static_cast<double>(next() % 1000) / 1000.0;
    return std::round((low + (high - low) * u) * 100) / 100;
  }
  std::uint64_t next() {
    std::uint64_t z = (state_ += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
  }

 private:
  std::uint64_t state_;
};

// Shortest round-trip text of a number ("0.25", "-3", "120").
std::string num(double value) {
  char text[32];
  const auto result = std::to_chars(text, text + sizeof text, value);
  return std::string(text, result.ptr);
}

std::size_t block_count(std::size_t elements) { return std::max<std::size_t>(1, elements / kElementsPerBlock); }

// Opens/closes the grouping around block i of n: groups of ten blocks inside groups of a hundred.
template <class Open, class Close>
void grouped(std::size_t n, std::string& out, Open open, Close close, auto&& block) {
  for (std::size_t i = 0; i < n; ++i) {
    if (i % 100 == 0) open(out);
    if (i % 10 == 0) open(out);
    block(i, out);
    if (i % 10 == 9 || i + 1 == n) close(out);
    if (i % 100 == 99 || i + 1 == n) close(out);
  }
}

std::string mimic(std::size_t elements) {
  Numbers r(1);
  std::string out =
      "def nod { head_rot_x <in=0.1,out=0.1,value=2>; head_rot_x <in=0.1,out=0.1,value=-1>; }\n"
      "main {\n";
  grouped(
      block_count(elements), out, [](std::string& o) { o += "{\n"; }, [](std::string& o) { o += "}\n"; },
      [&](std::size_t, std::string& o) {
        o += "[ jaw <min=0,max=" + num(r.between(0.02, 0.08)) + ",freq=" + num(r.between(2, 6)) + ",duration=0.8>;\n";
        o += "  head_rot_y <in=" + num(r.between(0.1, 0.3)) + ",hold=0.2,out=0.2,sin,value=" + num(r.between(-10, 10)) +
             ">;\n";
        o += "  eyelid_left ( 0 " + num(r.between(0.1, 0.4)) + " 0.6; 0 " + num(r.between(0.2, 0.9)) + " 0; )\n";
        o += "  { head_rot_x <in=0.1,hold=0.1,out=0.1,value=" + num(r.between(1, 5)) +
             ">; head_rot_x <in=0.1,out=0.1,value=" + num(r.between(-3, 0)) + ",connect>; }\n";
        o += "  nod;\n";
        o += "  jaw <right,hold=0.2,value=" + num(r.between(0.02, 0.1)) + ",overwrite>;\n";
        o += "  eyelid_right <in=0.2,out=0.2,exp,value=" + num(r.between(0.1, 0.5)) + ">; ]\n";
      });
  return out + "}\n";
}

std::string fml(std::size_t elements) {
  Numbers r(2);
  std::string out =
      "<?xml version=\"1.0\"?>\n<fml>\n  <model>\n    <template name=\"nod\">\n      <seq>\n"
      "        <hdmv type=\"pitch\" val=\"8\" duration=\"150ms\"/>\n"
      "        <hdmv type=\"pitch\" val=\"0\" duration=\"150ms\"/>\n      </seq>\n    </template>\n"
      "  </model>\n  <story>\n";
  int depth = 0;  // the groups of a hundred are actions, those of ten seqs
  grouped(
      block_count(elements), out, [&](std::string& o) { o += depth++ == 0 ? "  <action>\n" : "   <seq>\n"; },
      [&](std::string& o) { o += --depth == 0 ? "  </action>\n" : "   </seq>\n"; },
      [&](std::size_t i, std::string& o) {
        o += "    <par>\n";
        o += "      <hdmv type=\"yaw\" val=\"" + num(r.between(-20, 20)) + "\" duration=\"0.4s\"/>\n";
        if (i % 10 == 9) {
          o += "      <expr type=\"normal\" duration=\"0.3s\"/>\n";
        } else {
          o += "      <expr type=\"" + std::string(i % 2 ? "smile" : "surprise") + "\" val=\"" +
               num(r.between(20, 90)) + "\" duration=\"0.3s\"/>\n";
        }
        o += "      <fap type=\"open_jaw\" val=\"" + num(r.between(100, 400)) + "\" duration=\"0.2s\"/>\n";
        o += "      <param type=\"jaw\" val=\"" + num(r.between(0.02, 0.1)) + "\" duration=\"0.3s\"/>\n";
        o += "      <seq>\n        <hdmv type=\"roll\" val=\"" + num(r.between(-5, 5)) +
             "\" duration=\"200ms\"/>\n        <behavior name=\"nod\"/>\n"
             "        <wait duration=\"0.1s\"/>\n      </seq>\n";
        o += "      <fap type=\"raise_l_i_eyebrow\" val=\"" + num(r.between(20, 120)) +
             "\" duration=\"0.5s\" begin=\"0.1s\"/>\n";
        o += "    </par>\n";
      });
  return out + "  </story>\n</fml>\n";
}

std::string xmto(std::size_t elements, bool to_animations) {
  Numbers r(to_animations ? 4 : 3);
  std::string out =
      "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      "<XMT-O xmlns=\"urn:mpeg:mpeg4:xmto:schema:2002\">\n  <body>\n   <seq>\n";
  grouped(
      block_count(elements), out, [](std::string& o) { o += "   <seq>\n"; }, [](std::string& o) { o += "   </seq>\n"; },
      [&](std::size_t, std::string& o) {
        o += "    <par>\n";
        o += "      <animate attributeName=\"open_jaw\" values=\"0;" + num(r.between(100, 500)) +
             ";0\" keyTimes=\"0;0.4;1\" dur=\"0.8s\"/>\n";
        if (to_animations) {
          o += "      <animate attributeName=\"head_yaw\" to=\"" + num(r.between(-2000, 2000)) +
               "\" dur=\"0.4s\" fill=\"freeze\"/>\n";
        } else {
          o += "      <animate attributeName=\"head_yaw\" from=\"0\" to=\"" + num(r.between(-2000, 2000)) +
               "\" dur=\"0.4s\"/>\n";
        }
        o += "      <animate attributeName=\"raise_l_i_eyebrow\" by=\"" + num(r.between(20, 80)) +
             "\" begin=\"0.1s\" dur=\"0.3s\" additive=\"sum\"/>\n";
        o += "      <animate attributeName=\"raise_r_i_eyebrow\" values=\"10;" + num(r.between(40, 90)) +
             ";30\" calcMode=\"discrete\" dur=\"0.6s\"/>\n";
        if (to_animations) {
          o += "      <animate attributeName=\"lower_t_midlip\" to=\"" + num(r.between(-100, 0)) +
               "\" begin=\"0.3s\" dur=\"0.5s\"/>\n";
        } else {
          o += "      <animate attributeName=\"lower_t_midlip\" values=\"0;" + num(r.between(50, 100)) +
               ";0;50\" calcMode=\"paced\" dur=\"0.8s\"/>\n";
        }
        o += "      <seq>\n        <set attributeName=\"viseme.PP\" to=\"63\" dur=\"0.2s\"/>\n"
             "        <set attributeName=\"viseme.aa\" to=\"" +
             num(r.between(20, 63)) + "\" dur=\"0.2s\"/>\n      </seq>\n";
        o += "      <animate attributeName=\"head_roll\" from=\"0\" to=\"" + num(r.between(50, 200)) +
             "\" dur=\"0.2s\" repeatCount=\"3\" accumulate=\"sum\"/>\n";
        o += "    </par>\n";
      });
  return out + "   </seq>\n  </body>\n</XMT-O>\n";
}

// BML 1.0: a block's first face lexeme starts at the end of the previous block's (a chain through
// the whole document, solved in one pass), and the block's other behaviours are placed by sync
// references to it.
std::string bml(std::size_t elements) {
  static constexpr const char* kLexemes[] = {"RAISE_BROWS", "LOWER_BROWS", "OPEN_MOUTH",    "RAISE_MOUTH_CORNERS",
                                             "CLOSE_EYES",  "WIDEN_EYES",  "OBLIQUE_BROWS", "LOWER_MOUTH_CORNERS"};
  Numbers r(3);
  std::string out =
      "<?xml version=\"1.0\"?>\n<bml xmlns=\"http://www.bml-initiative.org/bml/bml-1.0\" id=\"bml1\" "
      "characterId=\"agent\">\n";
  for (std::size_t i = 0; i < block_count(elements); ++i) {
    const std::string id = "l" + std::to_string(i);
    const auto at = [&](double offset) { return "\"" + id + ":start+" + num(offset) + "\""; };
    const auto lexeme = [&](std::size_t k) { return std::string(kLexemes[(i + k) % 8]); };
    out += "  <faceLexeme id=\"" + id + "\" lexeme=\"" + lexeme(0) + "\" amount=\"" + num(r.between(0.3, 1)) +
           "\" start=" + (i == 0 ? std::string("\"0\"") : "\"l" + std::to_string(i - 1) + ":end\"") +
           " end=" + at(0.8) + "/>\n";
    static constexpr double kSpans[][2] = {{0.1, 0.3}, {0.2, 0.5}, {0.3, 0.7}};
    for (std::size_t k = 1; k <= 3; ++k)
      out += "  <faceLexeme id=\"" + id + "f" + std::to_string(k) + "\" lexeme=\"" + lexeme(k) + "\" amount=\"" +
             num(r.between(0.2, 0.8)) + "\" start=" + at(kSpans[k - 1][0]) + " end=" + at(kSpans[k - 1][1]) + "/>\n";
    out += "  <faceFacs id=\"" + id + "a\" au=\"12\" amount=\"" + num(r.between(0.2, 0.8)) + "\" start=" + at(0) +
           " end=" + at(0.6) + "/>\n";
    out += "  <faceFacs id=\"" + id + "b\" au=\"" + (i % 2 ? "1" : "4") + "\" side=\"" + (i % 3 ? "BOTH" : "LEFT") +
           "\" amount=\"" + num(r.between(0.2, 0.8)) + "\" start=" + at(0.2) + " end=" + at(0.7) + "/>\n";
    out += "  <head id=\"" + id + "h\" lexeme=\"" + (i % 2 ? "NOD" : "SHAKE") + "\" repetition=\"2\" amount=\"" +
           num(r.between(0.2, 0.8)) + "\" start=" + at(0.05) + " end=" + at(0.65) + "/>\n";
    out += "  <head id=\"" + id + "t\" lexeme=\"TILT\" amount=\"" + num(r.between(0.1, 0.5)) + "\" start=" + at(0.4) +
           " end=" + at(0.75) + "/>\n";
  }
  return out + "</bml>\n";
}

}  // namespace

const char* name(ScriptKind kind) {
  switch (kind) {
    case ScriptKind::mimic:
      return "mimic";
    case ScriptKind::fml:
      return "fml";
    case ScriptKind::xmto:
      return "xmto";
    case ScriptKind::xmto_to:
      return "xmto-to";
    case ScriptKind::bml:
      return "bml";
  }
  return "?";
}

const char* extension(ScriptKind kind) {
  switch (kind) {
    case ScriptKind::mimic:
      return ".mimic";
    case ScriptKind::fml:
      return ".fml";
    case ScriptKind::xmto:
    case ScriptKind::xmto_to:
      return ".xmt";
    case ScriptKind::bml:
      return ".bml";
  }
  return "";
}

bool parse_script_kind(std::string_view text, ScriptKind& kind) {
  for (const ScriptKind k : kScriptKinds) {
    if (text == name(k)) {
      kind = k;
      return true;
    }
  }
  return false;
}

std::string generate_script(ScriptKind kind, std::size_t elements) {
  switch (kind) {
    case ScriptKind::mimic:
      return mimic(elements);
    case ScriptKind::fml:
      return fml(elements);
    case ScriptKind::xmto:
      return xmto(elements, false);
    case ScriptKind::xmto_to:
      return xmto(elements, true);
    case ScriptKind::bml:
      return bml(elements);
  }
  return {};
}

}  // namespace fapc::bench
