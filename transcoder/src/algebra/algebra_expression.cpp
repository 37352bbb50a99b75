// Grammar (docs/algebra.md):
//   overlap := sum ('|' sum)*
//   sum     := product ('+' ['[' NUMBER ']'] product)*
//   product := NUMBER '*' product | postfix ('*' NUMBER)*
//   postfix := primary ('[' MASK ']' | '@' INTEGER | '>>' NUMBER)*
//   primary := NAME | '"' NAME '"' | '(' overlap ')'
#include "fapc/transcoder/algebra_expression.hpp"

#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>

#include "fapc/codec/nesting_limit.hpp"
#include "fapc/transcoder/codes.hpp"

namespace fapc::algebra {
namespace {

// The frames one expression may make in all, as a multiple of the frame limit: a long chain of
// operators, each within the limit, is refused before it takes minutes (docs/security.md).
constexpr int kWorkFactor = 4;

// An operand with what only an overlap uses.
struct Term {
  Value value;
  std::optional<Mask> mask;
  std::optional<int> priority;
  int column = 0;
};

bool name_char(char c) {
  return !std::isspace(static_cast<unsigned char>(c)) && c != '+' && c != '*' && c != '|' && c != '[' && c != ']' &&
         c != '(' && c != ')' && c != '@' && c != '"' && c != '>';
}

// A state meets an animation: the state holds on every slot of the animation's grid.
Animation broadcast(const FacialState& state, const Animation& like) {
  Animation out;
  out.fps = like.fps;
  out.frames.assign(std::max<std::size_t>(like.size(), 1), state);
  for (int fap = 3; fap <= 68; ++fap) {
    if (state.at(fap) != 0) out.carried.set(static_cast<std::size_t>(fap - 3));
  }
  return out;
}

class Evaluator {
 public:
  Evaluator(std::string_view text, const OperandLoader& load, std::int64_t max_frames)
      : text_(text), load_(load), max_frames_(max_frames) {}

  Result<Value> run() {
    Result<Term> result = overlap();
    if (!result) return result.error();
    skip_blanks();
    if (at_ < text_.size())
      return error(codes::algebra::unexpected_character, at_, "unexpected '" + std::string(1, text_[at_]) + "'");
    if (result->priority)
      return error(codes::algebra::priority_outside_overlap, static_cast<std::size_t>(result->column - 1),
                   "'@' gives a priority to an operand of '|'; there is no '|' here");
    if (result->mask) return masked(*result);
    return result->value;
  }

 private:
  std::string_view text_;
  const OperandLoader& load_;
  std::int64_t max_frames_;
  // Frames made in all (operands loaded, delayed, brought to one grid by an operator): each
  // operator may stay under max_frames while thousands of them together would take minutes.
  double made_ = 0;
  std::size_t at_ = 0;
  // Parentheses and amplifiers ("2 * 2 * x") recurse; deeper than kMaxNestingDepth is refused
  // before the stack can run out.
  int depth_ = 0;

  Diagnostic too_deep(std::size_t offset) const {
    return nesting_too_deep(Location::text("<expression>", 1, static_cast<int>(offset) + 1),
                            "parentheses and amplifiers", std::string(text_));
  }

  // Before an operator brings `operands` to one frame grid: the slots that grid will have (the
  // highest frame rate, the longest animation), against max_frames.
  std::optional<Diagnostic> too_many_frames(std::size_t offset, const std::vector<const Value*>& operands) {
    int fps = 0;
    for (const Value* v : operands)
      if (!v->state) fps = std::max(fps, v->animation.fps);
    double slots = 0;
    for (const Value* v : operands)
      if (!v->state && v->animation.fps > 0)
        slots = std::max(slots, std::ceil(static_cast<double>(v->animation.size()) * fps / v->animation.fps));
    if (slots > static_cast<double>(max_frames_)) {
      char what[96];
      std::snprintf(what, sizeof what, "this operator makes %.15g frames at %d fps", slots, fps);
      return frames_limit(offset, what);
    }
    return too_much_work(offset, slots);
  }
  // Counts `frames` more made, against kWorkFactor times max_frames for the whole expression.
  std::optional<Diagnostic> too_much_work(std::size_t offset, double frames) {
    made_ += frames;
    const double budget = kWorkFactor * static_cast<double>(max_frames_);
    if (made_ <= budget) return std::nullopt;
    char what[160];
    std::snprintf(what, sizeof what,
                  "the operators up to here make %.15g frames in all, more than %d times the frame limit of %lld "
                  "(--max-frames N raises it)",
                  made_, kWorkFactor, static_cast<long long>(max_frames_));
    Diagnostic d =
        make_error(codes::limit::frames, Location::text("<expression>", 1, static_cast<int>(offset) + 1), what);
    d.source_line = std::string(text_);
    return d;
  }
  Diagnostic frames_limit(std::size_t offset, const std::string& what) const {
    Limits limits;
    limits.max_frames = max_frames_;
    Diagnostic d =
        limit_error(Location::text("<expression>", 1, static_cast<int>(offset) + 1), what, Limit::frames, limits);
    d.source_line = std::string(text_);
    return d;
  }

  Diagnostic error(ErrorCode code, std::size_t offset, const std::string& message) const {
    return make_error(code, Location::text("<expression>", 1, static_cast<int>(offset) + 1), message,
                      std::string(text_));
  }
  Diagnostic retold_at(const Diagnostic& inner, std::size_t offset, const std::string& message) const {
    return retold(inner, Location::text("<expression>", 1, static_cast<int>(offset) + 1), message, std::string(text_));
  }
  void skip_blanks() {
    while (at_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[at_]))) ++at_;
  }
  bool accept(std::string_view token) {
    skip_blanks();
    if (text_.substr(at_, token.size()) != token) return false;
    at_ += token.size();
    return true;
  }

  Result<double> number() {
    skip_blanks();
    const std::size_t start = at_;
    double value = 0;
    const auto [end, status] = std::from_chars(text_.data() + at_, text_.data() + text_.size(), value);
    if (status != std::errc{} || !std::isfinite(value))
      return error(codes::algebra::expected_number, start, "expected a number");
    at_ = static_cast<std::size_t>(end - text_.data());
    return value;
  }
  bool number_ahead() {
    skip_blanks();
    if (at_ >= text_.size()) return false;
    const char c = text_[at_];
    return std::isdigit(static_cast<unsigned char>(c)) || c == '-' ||
           (c == '.' && at_ + 1 < text_.size() && std::isdigit(static_cast<unsigned char>(text_[at_ + 1])));
  }

  Result<Term> overlap() {
    std::vector<Term> terms;
    for (;;) {
      Result<Term> term = sum();
      if (!term) return term.error();
      terms.push_back(std::move(*term));
      if (!accept("|")) break;
    }
    if (terms.size() == 1) return std::move(terms.front());
    // States meet animations on the animations' grid; then the frames are folded.
    const Animation* grid = nullptr;
    for (const Term& t : terms) {
      if (!t.value.state) grid = &t.value.animation;
    }
    std::vector<const Value*> operands;
    for (const Term& t : terms) operands.push_back(&t.value);
    if (auto bad = too_many_frames(static_cast<std::size_t>(terms.front().column - 1), operands)) return *bad;
    std::vector<LayeredAnimation> layers;
    for (const Term& t : terms) {
      if (!t.priority) {
        return error(codes::algebra::priority_missing, static_cast<std::size_t>(t.column - 1),
                     "every operand of '|' needs a priority ('@2')");
      }
      layers.push_back(
          LayeredAnimation{t.value.state ? broadcast(*t.value.state, grid ? *grid : Animation{}) : t.value.animation,
                           t.mask.value_or(Mask::all()), *t.priority});
    }
    Result<Animation> folded = fapc::algebra::overlap(layers);
    if (!folded)
      return retold_at(folded.error(), static_cast<std::size_t>(terms.front().column - 1), folded.error().message);
    Term out;
    out.column = terms.front().column;
    if (!grid) {
      out.value.state = folded->frames.front().value_or(FacialState{});
    } else {
      out.value.animation = std::move(*folded);
    }
    return out;
  }

  Result<Term> sum() {
    Result<Term> left = product();
    if (!left) return left.error();
    for (;;) {
      skip_blanks();
      const std::size_t at = at_;
      if (!accept("+")) return left;
      double v = 0.5;
      if (accept("[")) {
        Result<double> weight = number();
        if (!weight) return weight.error();
        if (*weight < 0 || *weight > 1)
          return error(codes::algebra::weight_out_of_range, at, "the sum's weight must be within 0..1");
        v = *weight;
        if (!accept("]")) return error(codes::algebra::syntax, at_, "expected ']' after the sum's weight");
      }
      Result<Term> right = product();
      if (!right) return right.error();
      if (auto bad = overlap_only(*left); bad) return *bad;
      if (auto bad = overlap_only(*right); bad) return *bad;
      if (auto bad = too_many_frames(at, {&left->value, &right->value})) return *bad;
      left->value =
          combine(left->value, right->value, [v](const auto& s, const auto& t) { return fapc::algebra::sum(s, t, v); });
    }
  }

  Result<Term> product() {
    if (number_ahead()) {
      const std::size_t w_at = at_;
      Result<double> w = number();
      if (!w) return w.error();
      if (!accept("*")) return error(codes::algebra::syntax, at_, "expected '*' after the amplifier " + format(*w));
      if (depth_ >= kMaxNestingDepth) return too_deep(at_);
      ++depth_;
      Result<Term> operand = product();
      --depth_;
      if (!operand) return operand.error();
      if (auto bad = overlap_only(*operand); bad) return *bad;
      if (auto bad = out_of_range(w_at, operand->value, *w); bad) return *bad;
      amplify_in_place(operand->value, *w);
      return operand;
    }
    Result<Term> operand = postfix();
    if (!operand) return operand.error();
    while (accept("*")) {
      skip_blanks();
      const std::size_t w_at = at_;
      Result<double> w = number();
      if (!w) return w.error();
      if (auto bad = overlap_only(*operand); bad) return *bad;
      if (auto bad = out_of_range(w_at, operand->value, *w); bad) return *bad;
      amplify_in_place(operand->value, *w);
    }
    return operand;
  }

  Result<Term> postfix() {
    Result<Term> term = primary();
    if (!term) return term.error();
    // Chained delays ("x >> 1 >> 1 ...") add up and are applied once, when the term ends: one
    // copy of the animation, not one per '>>' (1,500 of them once took seconds and gigabytes).
    long delay_frames = 0;
    for (;;) {
      skip_blanks();
      const std::size_t at = at_;
      if (accept("[")) {
        const std::size_t close = text_.find(']', at_);
        if (close == std::string_view::npos) return error(codes::algebra::syntax, at, "'[' without ']'");
        Result<Mask> mask = parse_mask(text_.substr(at_, close - at_));
        if (!mask)
          return retold_at(mask.error(), at_ + static_cast<std::size_t>(mask.error().where.column),
                           mask.error().message);
        term->mask = *mask;
        at_ = close + 1;
      } else if (accept("@")) {
        skip_blanks();
        int priority = 0;
        const auto [end, status] = std::from_chars(text_.data() + at_, text_.data() + text_.size(), priority);
        if (status != std::errc{}) return error(codes::algebra::syntax, at_, "expected an integer priority after '@'");
        at_ = static_cast<std::size_t>(end - text_.data());
        term->priority = priority;
      } else if (accept(">>")) {
        Result<double> seconds = number();
        if (!seconds) return seconds.error();
        if (term->value.state)
          return error(codes::algebra::delay_of_state, at, "'>>' delays an animation; this operand is a state");
        // A day of frames is already more than any face animation; beyond it is a typo. A
        // negative delay would cut the animation's start away (all of it, for a short one): the
        // operator only delays (docs/algebra.md).
        if (*seconds < 0 || *seconds > 86400)
          return error(codes::algebra::delay_out_of_range, at,
                       "a delay is from 0 to 86400 s (a day); " + format(*seconds) + " is not");
        const long frames = std::lround(*seconds * term->value.animation.fps);
        const double slots = static_cast<double>(term->value.animation.size()) + static_cast<double>(delay_frames) +
                             static_cast<double>(frames);
        if (slots > static_cast<double>(max_frames_)) {
          char what[96];
          std::snprintf(what, sizeof what, "the delayed animation spans %.15g frames at %d fps", slots,
                        term->value.animation.fps);
          return frames_limit(at, what);
        }
        delay_frames += frames;
      } else {
        if (delay_frames > 0) {
          const double delayed =
              static_cast<double>(term->value.animation.size() + static_cast<std::size_t>(delay_frames));
          if (auto bad = too_much_work(at_, delayed)) return *bad;
          delay_in_place(term->value.animation, delay_frames);
        }
        return term;
      }
    }
  }

  Result<Term> primary() {
    skip_blanks();
    const std::size_t start = at_;
    if (accept("(")) {
      if (depth_ >= kMaxNestingDepth) return too_deep(start);
      ++depth_;
      Result<Term> inner = overlap();
      --depth_;
      if (!inner) return inner.error();
      if (!accept(")")) return error(codes::algebra::syntax, at_, "expected ')'");
      inner->column = static_cast<int>(start) + 1;
      if (inner->mask) {
        inner->value = masked(*inner);
        inner->mask.reset();
      }
      inner->priority.reset();
      return inner;
    }
    std::string name;
    if (accept("\"")) {
      const std::size_t close = text_.find('"', at_);
      if (close == std::string_view::npos) return error(codes::algebra::syntax, start, "'\"' without a closing '\"'");
      name = std::string(text_.substr(at_, close - at_));
      at_ = close + 1;
    } else {
      while (at_ < text_.size() && name_char(text_[at_])) ++at_;
      name = std::string(text_.substr(start, at_ - start));
    }
    if (name.empty()) {
      return error(codes::algebra::syntax, start,
                   at_ < text_.size() ? "expected a file, a number or '(', found '" + std::string(1, text_[at_]) + "'"
                                      : "expected a file, a number or '(' at the end");
    }
    Result<Value> value = load_(name, static_cast<int>(start) + 1);
    if (value && !value->state)
      if (auto bad = too_much_work(start, static_cast<double>(value->animation.size()))) return *bad;
    if (!value) {
      // A problem with the operand as a whole (it cannot be opened, it is too long) is reported
      // where the expression names it; a problem inside it, at its own place.
      const Diagnostic& inner = value.error();
      if (inner.where.line > 0 || inner.where.byte_offset >= 0) return inner;
      return retold_at(inner, start, "operand '" + inner.where.file + "': " + inner.message);
    }
    return Term{std::move(*value), std::nullopt, std::nullopt, static_cast<int>(start) + 1};
  }

  std::optional<Diagnostic> overlap_only(const Term& t) const {
    if (!t.mask && !t.priority) return std::nullopt;
    return error(codes::algebra::mask_outside_overlap, static_cast<std::size_t>(t.column - 1),
                 "masks '[...]' and priorities '@N' belong to operands of '|'");
  }

  static Value masked(const Term& t) {
    Value out = t.value;
    const auto apply = [&](FacialState& s) {
      for (int fap = 3; fap <= 68; ++fap) {
        if (!t.mask->covers(fap)) s.at(fap) = 0;
      }
    };
    if (out.state) apply(*out.state);
    for (auto& frame : out.animation.frames) {
      if (frame) apply(*frame);
    }
    out.animation.carried &= t.mask->bits;
    return out;
  }

  // An amplifier that takes some FAP value past what a FAP value can hold (32 bits) would
  // saturate it silently: refused at the amplifier, naming the first such value.
  std::optional<Diagnostic> out_of_range(std::size_t offset, const Value& value, double w) const {
    const auto check = [&](const FacialState& s) -> std::optional<Diagnostic> {
      for (int fap = 3; fap <= kFapCount; ++fap) {
        const double product = std::round(w * s.at(fap));
        if (product <= 2147483647.0 && product >= -2147483648.0) continue;
        return error(codes::algebra::value_overflow, offset,
                     "the amplifier " + format(w) + " takes FAP " + std::to_string(fap) + " from " +
                         std::to_string(s.at(fap)) + " to " + format(product) +
                         ", beyond the 32-bit range of FAP values");
      }
      return std::nullopt;
    };
    if (value.state) return check(*value.state);
    for (const auto& frame : value.animation.frames)
      if (frame)
        if (auto bad = check(*frame)) return bad;
    return std::nullopt;
  }

  static void amplify_in_place(Value& value, double w) {
    if (value.state) {
      *value.state = fapc::algebra::amplify(*value.state, w);
    } else {
      value.animation = fapc::algebra::amplify(value.animation, w);
    }
  }

  template <class Op>
  static Value combine(const Value& a, const Value& b, Op op) {
    Value out;
    if (a.state && b.state) {
      out.state = op(*a.state, *b.state);
      return out;
    }
    // Only a state is turned into frames; an animation operand is used where it is (a chain of
    // thousands of '+' would otherwise copy both operands at every step).
    Animation x_store, y_store;
    if (a.state) x_store = broadcast(*a.state, b.animation);
    if (b.state) y_store = broadcast(*b.state, a.animation);
    out.animation = op(a.state ? x_store : a.animation, b.state ? y_store : b.animation);
    return out;
  }

  static std::string format(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", v);
    return text;
  }
};

}  // namespace

Result<Value> evaluate(std::string_view expression, const OperandLoader& load, std::int64_t max_frames) {
  return Evaluator(expression, load, max_frames).run();
}

}  // namespace fapc::algebra
