#include "xmto/smil_timing.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <string>

#include "fapc/xml/text.hpp"
#include "fapc/xmto/codes.hpp"
#include "fapc/xmto/xmto.hpp"

namespace fapc::xmto {
namespace {

constexpr const char* kClockForms = "a clock value such as 3, 3s, 250ms or 00:00:03.5";

// Why a begin or end value is not a plain offset: names the SMIL feature it uses.
std::string unsupported_offset(std::string_view value) {
  if (value.find(';') != std::string_view::npos) return "lists of times are not supported";
  if (value.starts_with("wallclock(")) return "wallclock times are not supported";
  if (value.starts_with("accesskey(")) return "accesskey events are not supported";
  if (value.find('.') != std::string_view::npos && !std::isdigit(static_cast<unsigned char>(value[0])))
    return "sync-base and event timing are not supported";
  return "expected " + std::string(kClockForms) + ", optionally signed";
}

class Reader {
 public:
  Reader(const xml::XmlDocument& doc, const xmlNode* element) : doc_(doc), element_(element) {}

  std::optional<Diagnostic> error;

  // begin and end: ("+" | "-")? clock value, or "indefinite".
  void offset(const char* name, std::optional<double>& value, bool& indefinite) {
    const auto text = xml::attribute(element_, name);
    if (!text || error) return;
    std::string_view s = xml::trim(*text);
    if (s == "indefinite") {
      indefinite = true;
      return;
    }
    double sign = 1;
    if (!s.empty() && (s.front() == '+' || s.front() == '-')) {
      sign = s.front() == '-' ? -1 : 1;
      s = xml::trim(s.substr(1));
    }
    if (const auto seconds = xml::parse_clock_value(s)) {
      value = sign * *seconds;
      return;
    }
    fail(codes::xmto::unsupported_offset, name, std::string(name) + " '" + *text + "': " + unsupported_offset(s));
  }

  // dur and repeatDur: a clock value, "indefinite" (and "media" for dur: the implicit duration).
  void duration(const char* name, std::optional<double>& value, bool& indefinite, bool allow_media) {
    const auto text = xml::attribute(element_, name);
    if (!text || error) return;
    const std::string_view s = xml::trim(*text);
    if (s == "indefinite") {
      indefinite = true;
      return;
    }
    if (allow_media && s == "media") return;
    const auto seconds = xml::parse_clock_value(s);
    if (!seconds) {
      fail(codes::xmto::bad_time, name,
           std::string(name) + " '" + *text + "': expected " + kClockForms +
               (allow_media ? ", indefinite or media" : " or indefinite"));
    } else if (*seconds <= 0) {
      fail(codes::xmto::bad_time, name, std::string(name) + " must be greater than 0, found '" + *text + "'");
    } else {
      value = seconds;
    }
  }

  void repeat_count(std::optional<double>& value, bool& indefinite) {
    const auto text = xml::attribute(element_, "repeatCount");
    if (!text || error) return;
    const std::string_view s = xml::trim(*text);
    if (s == "indefinite") {
      indefinite = true;
      return;
    }
    double count = 0;
    const auto [end, failure] = std::from_chars(s.data(), s.data() + s.size(), count);
    if (s.empty() || failure != std::errc() || end != s.data() + s.size() || !std::isfinite(count) || count <= 0) {
      fail(codes::xmto::bad_repeat, "repeatCount",
           "repeatCount '" + *text + "': expected a number greater than 0 or indefinite");
      return;
    }
    value = count;
  }

  void fill(SmilTiming& timing) {
    const auto text = xml::attribute(element_, "fill");
    if (!text || error) return;
    const std::string_view s = xml::trim(*text);
    if (s == "freeze" || s == "hold") {
      timing.fill = Fill::freeze;
    } else if (s == "remove" || s == "transition") {
      timing.fill = Fill::remove;
    } else if (s == "auto") {
      timing.fill_auto = true;
    } else if (s != "default") {
      fail(codes::xmto::unsupported_keyword, "fill",
           "fill '" + *text + "': expected freeze, remove, hold, transition, auto or default");
    }
  }

 private:
  const xml::XmlDocument& doc_;
  const xmlNode* element_;

  void fail(ErrorCode code, const char* attribute, std::string message) {
    if (!error) error = doc_.error(code, element_, attribute, std::move(message));
  }
};

}  // namespace

Fill SmilTiming::effective_fill(Fill inherited) const {
  if (fill) return *fill;
  if (fill_auto) {
    return has_duration_attribute() || end ? Fill::remove : Fill::freeze;
  }
  return inherited;
}

Result<SmilTiming> read_smil_timing(const xml::XmlDocument& doc, const xmlNode* element) {
  SmilTiming timing;
  Reader reader(doc, element);
  reader.offset("begin", timing.begin, timing.begin_indefinite);
  bool end_indefinite = false;  // SMIL: the same as no end
  reader.offset("end", timing.end, end_indefinite);
  reader.duration("dur", timing.dur, timing.dur_indefinite, true);
  reader.repeat_count(timing.repeat_count, timing.repeat_count_indefinite);
  reader.duration("repeatDur", timing.repeat_dur, timing.repeat_dur_indefinite, false);
  reader.fill(timing);
  if (reader.error) return *reader.error;
  return timing;
}

Timing to_schedule_timing(const SmilTiming& smil, std::optional<double> implicit) {
  Timing timing;
  timing.offset = smil.begin.value_or(0);
  timing.duration = smil.dur ? smil.dur : (smil.dur_indefinite ? std::nullopt : implicit);
  timing.repeat = smil.repeat_count.value_or(1);
  // repeatDur without repeatCount repeats until repeatDur (or forever); with a count, whichever
  // ends first.
  const bool by_repeat_dur = !smil.repeat_count && (smil.repeat_dur || smil.repeat_dur_indefinite);
  timing.repeat_indefinite = smil.repeat_count_indefinite || by_repeat_dur;
  timing.repeat_duration = smil.repeat_dur;
  if (!smil.end) return timing;
  const double until_end = std::max(0.0, *smil.end - timing.offset);
  if (smil.has_duration_attribute()) {
    // Active duration = min(the duration dur and repeat give, end - begin). The scheduler's own
    // `end` would replace the first term instead of capping it.
    timing.repeat_duration = std::min(timing.repeat_duration.value_or(until_end), until_end);
  } else {
    // Only end: the element is active until it; nothing repeats.
    timing.duration = until_end;
  }
  return timing;
}

}  // namespace fapc::xmto
