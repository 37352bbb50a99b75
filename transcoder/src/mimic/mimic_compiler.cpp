// Mimic semantics (docs/mimic.md, "Timing and values"): check the parsed program, build the
// schedule tree (macros expanded), schedule it with the shared scheduler and lower the atomic
// actions to clips; `connect` is resolved last, once every clip has its place.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <map>
#include <set>
#include <sstream>
#include <unordered_map>
#include <utility>
#include <variant>

#include "action_params.hpp"
#include "chunked_vector.hpp"
#include "fapc/codec/fap_table.hpp"
#include "fapc/codec/file_io.hpp"
#include "fapc/codec/include_policy.hpp"
#include "fapc/codec/nesting_limit.hpp"
#include "fapc/timeline/schedule.hpp"
#include "fapc/transcoder/algebra.hpp"
#include "fapc/transcoder/codes.hpp"
#include "fapc/transcoder/expression_file.hpp"
#include "fapc/transcoder/mimic.hpp"
#include "mimic_lexer.hpp"
#include "mimic_parser.hpp"

namespace fapc {
namespace mimic {
namespace {

using Kind = ScheduleNode::Kind;

// Far more than any hand-written program expands to (an hour of animation at eight actions a
// second is 28800), and small enough to refuse within a second (an action costs a few µs).

struct Target {
  std::uint32_t name = 0;  // an index into Compiler::names_: a script names few targets
  double factor = 1;       // a defxpr entry's value: the amplifier applied to the fade's value
};

struct ListPoint {
  double time = 0;
  double value = 0;
};

// What lowering needs of a fade's parameters.
struct Fade {
  double in = 0, hold = 0, out = 0;
  double value = 0;  // the value written (an expression's: unused)
  Interpolation interpolation = Interpolation::linear;
  // connect: the fade ends at the value of the target's next clip; connect=x: at connect_to.
  enum class Connect : std::uint8_t { none, next, given };
  Connect connect = Connect::none;
  double connect_to = 0;
};

// One atomic action as lowering needs it, in under 90 bytes: a program has millions (all of
// ActionParams is 500 bytes).
struct Leaf {
  enum class Shape : std::uint8_t { fade, periodic, list };
  Shape shape = Shape::fade;
  // A defxpr instance: its targets' factors are already the amplified state (the fade's value
  // applied by the Algebra's amplifier), so the fade rises to the factor itself.
  bool expression = false;
  BlendMode blend = BlendMode::add;
  Position at;  // the action's, for the clips' sources
  // Its targets: an expression's are targets_[first_target, first_target + target_count) of the
  // Compiler; any other action has one, the name first_target, at factor 1.
  std::uint32_t first_target = 0;
  std::uint32_t target_count = 0;
  // A time-value list: list_points_[first_point, first_point + point_count) of the Compiler.
  std::uint32_t first_point = 0;
  std::uint32_t point_count = 0;
  std::variant<std::monostate, Fade, Periodic> curve;  // by shape (a list's points are apart)
};

struct Context {
  std::optional<BlendMode> blend;
  Action::Kind parent = Action::Kind::sequence;
  // Groups around this action, macro bodies included: a chain of macros nests as deep as their
  // groups together, and the schedule tree (and the recursion building it) is that deep.
  int depth = 0;
};

std::string format_number(double v) {
  std::ostringstream out;
  out << v;
  return out.str();
}

// Compiles while the parser reads: main's actions arrive one at a time (MainSink) and become
// schedule nodes at once, so that no tree of main's actions is ever held. The errors are those a
// compiler of the whole parsed program would give: a syntax error anywhere first, then (by rank)
// the definitions', a macro too big, main too big, and the first of the others in source order.
class Compiler final : public MainSink {
 public:
  Compiler(std::string_view source, const std::string& file, const ReaderOptions& options)
      : source_(source),
        file_(file),
        file_location_(Location::text(file, 0, 0)),
        options_(options),
        profile_(options.profile ? *options.profile : default_profile()) {}

  Result<MimicProgram> run() {
    if (Status parsed = parse_program(source_, file_, program_, *this); !parsed) return parsed.error();
    if (pending_) return std::move(pending_->diagnostic);
    ScheduleNode root = std::move(root_);
    if (main_params_->left) root.timing.offset += main_params_->left->value;
    ScheduleOptions schedule_options;
    schedule_options.max_runs = options_.limits.max_runs;
    Result<Schedule> scheduled = schedule(root, schedule_options);
    if (!scheduled) return with_source_line(scheduled.error());
    if (auto too_long = check_length(*scheduled); !too_long) return too_long.error();
    root = ScheduleNode{};  // the tree is scheduled: let it go before the clips are made
    MimicProgram out;
    out.timeline = lower(*scheduled);
    out.warnings = std::move(warnings_);
    return out;
  }

  // ---- main as it is parsed (MainSink) -------------------------------------------------------

  // What run() checked before building main when it had the whole tree, in the same order.
  void begin_main(const std::vector<Definition>&, const std::vector<Param>& main_params) override {
    if (auto defined = collect_definitions(); !defined) return hold(defined.error(), Rank::definitions);
    // Macro bombs are refused before anything is built: sizes are counted once per definition.
    for (const Definition& d : program_.definitions) {
      if (!d.expression && expanded_size(d.group) > run_limit()) {
        return hold(too_many_actions(d.group), Rank::macro_size);
      }
    }
    // Macro bodies are checked where they are written, even when no one uses them.
    for (const Definition& d : program_.definitions) {
      if (d.expression) continue;
      stack_ = {d.name};
      const Sizes keep = sizes();
      Result<ScheduleNode> body = build(d.group, Context{});
      truncate(keep);
      if (!body) return hold(body.error(), Rank::other);
    }
    stack_.clear();
    Result<ActionParams> main = read(main_params);
    if (!main) return hold(main.error(), Rank::other);
    if (main->right)
      return hold(error(codes::mimic::misplaced_parameter, main->right->at,
                        "'right' needs a parallel around it; main has none"),
                  Rank::other);
    if (const Param* p = atomic_param(*main)) {
      return hold(
          error(codes::mimic::misplaced_parameter, p->at, "'" + p->name() + "' applies to atomic actions, not to main"),
          Rank::other);
    }
    main_params_ = std::move(*main);
  }

  void open_group(const Action& group) override {
    const bool is_main = open_ == 0;
    if (open_ == frames_.size()) frames_.emplace_back();
    Frame& frame = frames_[open_++];
    frame.depth = is_main ? 0 : frames_[open_ - 2].depth + 1;
    frame.children.clear();
    main_size_ += 1;  // the group itself; its actions are counted as they come
    if (pending_) return;
    const Context context = is_main ? Context{main_params_->blend_mode(), Action::Kind::sequence, 0}
                                    : frames_[open_ - 2].inner(frame.depth);
    Result<Prepared> prepared = prepare(group, context);
    if (!prepared) return hold(prepared.error(), Rank::other);
    Result<ScheduleNode> node = group_node(group, *prepared);
    if (!node) return hold(node.error(), Rank::other);
    frame.node = std::move(*node);
    frame.blend = prepared->blend;
    frame.kind = group.kind;
  }

  void named_action(Action&& action) override {
    Frame& parent = frames_[open_ - 1];
    const int depth = parent.depth + 1;
    if (!pending_ || pending_->rank > Rank::main_size) {
      // main's size as run() counted it before building (expanded_size(main)): past the run
      // limit, the error points where overflowing(main) would.
      const double size = expanded_size(action);
      if (main_size_ + size > run_limit()) {
        hold(too_many_actions(overflowing(action, run_limit() - main_size_)), Rank::main_size);
      }
      main_size_ += size;
    }
    if (pending_) return;
    Result<ScheduleNode> built = build(action, parent.inner(depth));
    if (!built) return hold(built.error(), Rank::other);
    parent.children.push_back(std::move(*built));
  }

  void close_group() override {
    Frame& frame = frames_[--open_];
    if (pending_) return;
    // Exactly as many children as it has: the tree holds a node per action of the program.
    frame.node.children.reserve(frame.children.size());
    std::move(frame.children.begin(), frame.children.end(), std::back_inserter(frame.node.children));
    frame.children.clear();
    if (open_ == 0) {
      root_ = std::move(frame.node);
    } else {
      frames_[open_ - 1].children.push_back(std::move(frame.node));
    }
  }

 private:
  // Errors found while main is still being read, by the order run() used to check them in.
  enum class Rank { definitions, macro_size, main_size, other };
  struct Pending {
    Diagnostic diagnostic;
    Rank rank = Rank::other;
  };
  // A group of main being read: its node, and its children built so far.
  struct Frame {
    ScheduleNode node;
    std::vector<ScheduleNode> children;  // reused from group to group at this depth
    std::optional<BlendMode> blend;
    Action::Kind kind = Action::Kind::sequence;
    int depth = 0;
    Context inner(int child_depth) const { return Context{blend, kind, child_depth}; }
  };
  // build()'s reading of an action's parameters, before it looks at what the action is.
  struct Prepared {
    ActionParams params;
    Timing timing;
    std::optional<BlendMode> blend;
  };
  // How far the arenas reach, to drop what a macro body's check built.
  struct Sizes {
    std::size_t leaves = 0, targets = 0, points = 0;
  };

  std::string_view source_;
  const std::string& file_;
  const Location file_location_;  // copied per node: building a Location from the path costs more
  const ReaderOptions& options_;
  const Profile& profile_;
  Program program_;
  std::optional<Pending> pending_;
  std::optional<ActionParams> main_params_;
  std::vector<Frame> frames_;  // main's groups open around the parser, outermost first
  std::size_t open_ = 0;
  double main_size_ = 0;  // expanded_size(main) of what has been read
  ScheduleNode root_;
  std::map<std::string, const Definition*, std::less<>> macros_;
  std::map<std::string, algebra::FacialState, std::less<>> expressions_;
  // In big blocks, never copied as they grow (chunked_vector.hpp).
  ChunkedVector<Leaf> leaves_;
  ChunkedVector<Target> targets_;
  ChunkedVector<ListPoint> list_points_;
  // Target names, interned: each with what it writes (resolve_target), asked once per name.
  std::vector<std::string> names_;
  std::vector<std::vector<FapContribution>> name_contributions_;
  std::map<std::string, std::uint32_t, std::less<>> name_ids_;
  std::vector<std::string> stack_;  // macros being expanded, for recursion errors
  std::size_t actions_built_ = 0;
  std::map<std::string, double, std::less<>> sizes_;  // per macro: its body's expanded_size()
  std::set<std::string, std::less<>> sizing_;         // macros being sized (recursion)
  // While lowering: each clip's target name, and the clips that end with `connect`.
  std::vector<std::uint32_t> clip_names_;
  struct Connecting {
    std::size_t clip = 0;
    bool given = false;  // connect=x: end at `to`; else at the next clip's value
    double to = 0;
  };
  std::vector<Connecting> connecting_;
  static constexpr std::uint32_t kNoConnect = UINT32_MAX;
  Diagnostics warnings_;

  void hold(Diagnostic d, Rank rank) {
    if (!pending_ || rank < pending_->rank) pending_ = Pending{std::move(d), rank};
  }
  Sizes sizes() const { return {leaves_.size(), targets_.size(), list_points_.size()}; }
  void truncate(const Sizes& keep) {
    leaves_.truncate(keep.leaves);
    targets_.truncate(keep.targets);
    list_points_.truncate(keep.points);
  }

  // The interned id of a target name, with its contributions resolved once.
  std::uint32_t name_id(std::string_view name) {
    if (const auto found = name_ids_.find(name); found != name_ids_.end()) return found->second;
    const auto id = static_cast<std::uint32_t>(names_.size());
    names_.emplace_back(name);
    name_contributions_.push_back(resolve_target(name, profile_));
    name_ids_.emplace(std::string(name), id);
    return id;
  }
  const std::vector<FapContribution>& contributions(std::uint32_t id) const { return name_contributions_[id]; }

  double run_limit() const { return static_cast<double>(std::max<std::int64_t>(options_.limits.max_runs, 0)); }

  Diagnostic too_many_actions(const Action& action) const {
    Limits limits;
    limits.max_runs = options_.limits.max_runs;
    Diagnostic refused =
        limit_error(location(action.at), "the program has too many actions with macros expanded", Limit::runs, limits);
    refused.source_line = source_line(source_, action.at.line);
    return refused;
  }

  // How many times build() runs for `action` (groups, macro uses, atomic actions), each macro's
  // body counted once and remembered: a chain of forty macros that each use the one before twice
  // costs forty steps, not 2^40. Full counts, also past the depth limit (build() refuses those
  // programs itself); a use of a macro being counted is a recursion and counts 1 (build() says so).
  double expanded_size(const Action& action) {
    if (action.kind != Action::Kind::named) {
      double n = 1;
      for (const Action& child : action.children) n += expanded_size(child);
      return n;
    }
    const auto macro = macros_.find(action.name);
    if (macro == macros_.end() || macro->second->expression || sizing_.contains(action.name)) return 1;
    const auto known = sizes_.find(action.name);
    return 1 + (known != sizes_.end() ? known->second : size_macros_from(action.name));
  }

  // Counts the body of macro `name` and of every macro under it, deepest first, on a stack of our
  // own instead of recursion: a chain of 5000 macros must neither take the call stack 5000 deep
  // nor be walked again from each of its links (that took seconds).
  double size_macros_from(const std::string& name) {
    std::vector<std::pair<std::string, bool>> todo{{name, false}};  // (macro, its uses pushed)
    while (!todo.empty()) {
      auto& [macro, uses_pushed] = todo.back();
      const Action& body = macros_.find(macro)->second->group;
      if (sizes_.contains(macro)) {
        todo.pop_back();
      } else if (!uses_pushed) {
        uses_pushed = true;
        sizing_.insert(macro);
        push_uncounted_uses(body, todo);
      } else {
        // Every macro the body uses is counted now, or being counted (a recursion).
        const double size = expanded_size(body);
        sizes_.emplace(macro, size);
        sizing_.erase(macro);
        todo.pop_back();
      }
    }
    return sizes_.find(name)->second;
  }

  void push_uncounted_uses(const Action& action, std::vector<std::pair<std::string, bool>>& todo) {
    if (action.kind != Action::Kind::named) {
      for (const Action& child : action.children) push_uncounted_uses(child, todo);
      return;
    }
    const auto macro = macros_.find(action.name);
    if (macro == macros_.end() || macro->second->expression) return;
    if (!sizes_.contains(action.name) && !sizing_.contains(action.name)) todo.emplace_back(action.name, false);
  }

  // The action inside `action` where the count passes `budget`: where the error points.
  const Action& overflowing(const Action& action, double budget) {
    double left = budget - 1;
    if (action.kind == Action::Kind::named) {
      const auto macro = macros_.find(action.name);
      if (macro == macros_.end() || macro->second->expression || left < 0) return action;
      return overflowing(macro->second->group, left);
    }
    for (const Action& child : action.children) {
      const double size = expanded_size(child);
      if (size > left) return overflowing(child, left);
      left -= size;
    }
    return action;
  }

  Diagnostic error(ErrorCode code, Position at, const std::string& message) const {
    return make_error(code, location(at), message, source_line(source_, at.line));
  }
  Diagnostic with_source_line(Diagnostic d) const {
    if (d.where.file == file_) d.source_line = source_line(source_, d.where.line);
    return d;
  }
  Location location(Position at) const {
    Location where = file_location_;
    where.line = at.line;
    where.column = at.column;
    return where;
  }

  Result<ActionParams> read(const std::vector<Param>& params) const {
    return read_params(params,
                       [this](ErrorCode code, Position at, const std::string& m) { return error(code, at, m); });
  }

  // The first parameter that only an atomic action may have.
  static const Param* atomic_param(const ActionParams& p) {
    if (p.first_fade) return p.first_fade;
    if (p.first_periodic) return p.first_periodic;
    return p.function ? &*p.function : nullptr;
  }

  Status collect_definitions() {
    for (const Definition& d : program_.definitions) {
      if (macros_.contains(d.name))
        return error(codes::mimic::defined_twice, d.at, "'" + d.name + "' is defined twice");
      if (!resolve_target(d.name, profile_).empty()) {
        return error(codes::mimic::definition_name, d.at,
                     "'" + d.name + "' is an animation parameter; a definition needs another name");
      }
      macros_[d.name] = &d;
      if (!d.expression) continue;
      Result<algebra::FacialState> state = load_expression(d);
      if (!state) return state.error();
      expressions_[d.name] = *state;
    }
    return ok_status();
  }

  // The .xpr file as a facial state (FAP units, through the profile), by the Algebra's code.
  Result<algebra::FacialState> load_expression(const Definition& d) {
    Result<std::string> resolved = resolve_include(d.file, file_, options_.includes, location(d.file_at));
    if (!resolved) {
      Diagnostic refused = resolved.error();
      refused.source_line = source_line(source_, d.file_at.line);
      return refused;
    }
    const std::string& path = *resolved;
    Result<std::string> text = options_.read_file ? options_.read_file(path) : read_file_bytes(path);
    if (!text) {
      return error(codes::mimic::expression_file_unreadable, d.file_at,
                   "cannot read the expression file '" + d.file + "': " + text.error().message);
    }
    Result<std::vector<ExpressionEntry>> entries = parse_expression_file(*text, path);
    if (!entries) return entries.error();
    if (entries->empty())
      return error(codes::mimic::expression_file_empty, d.file_at,
                   "the expression file '" + d.file + "' sets no parameter");
    Result<algebra::FacialState> state = algebra::state_from_entries(*entries, profile_);
    if (!state) {
      Diagnostic problem = state.error();
      problem.source_line = source_line(*text, problem.where.line);
      return problem;
    }
    return state;
  }

  Result<ScheduleNode> build(const Action& action, const Context& context) {
    Result<Prepared> prepared = prepare(action, context);
    if (!prepared) return prepared.error();
    if (action.kind != Action::Kind::named) {
      Result<ScheduleNode> node = group_node(action, *prepared);
      if (!node) return node.error();
      node->children.reserve(action.children.size());
      for (const Action& child : action.children) {
        Result<ScheduleNode> built = build(child, Context{prepared->blend, action.kind, context.depth + 1});
        if (!built) return built.error();
        node->children.push_back(std::move(*built));
      }
      return node;
    }
    if (const auto macro = macros_.find(action.name); macro != macros_.end() && !macro->second->expression) {
      return instantiate(action, *macro->second, prepared->params, prepared->timing,
                         Context{prepared->blend, Action::Kind::sequence, context.depth + 1});
    }
    return atomic(action, std::move(prepared->params), prepared->timing, prepared->blend.value_or(BlendMode::add),
                  context);
  }

  // What build() does for every action before it looks at its kind: the depth and count limits,
  // the parameters, the timing and the blend mode its children inherit.
  Result<Prepared> prepare(const Action& action, const Context& context) {
    if (context.depth >= kMaxNestingDepth) {
      return nesting_too_deep(location(action.at), "groups (with macros expanded)",
                              source_line(source_, action.at.line));
    }
    // Macros that use each other twice double with every level: forty lines can ask for 2^40
    // actions. Counted over the whole compilation (the macro bodies' own checks included).
    // The bound is the run limit (each action is at least one run), so a program of 10^6
    // honest actions passes with the defaults. Most programs over it are refused before.
    if (static_cast<double>(++actions_built_) > run_limit()) return too_many_actions(action);
    Result<ActionParams> params = read(action.params);
    if (!params) return params.error();
    Prepared prepared;
    if (params->left) prepared.timing.offset = params->left->value;
    if (params->right) {
      if (context.parent != Action::Kind::parallel) {
        return error(codes::mimic::misplaced_parameter, params->right->at,
                     "right alignment is only allowed in a parallel, not in a sequence");
      }
      prepared.timing.align_right = params->right->value;
    }
    prepared.blend = params->blend_mode() ? params->blend_mode() : context.blend;
    prepared.params = std::move(*params);
    return prepared;
  }

  // A group's node, without its children.
  Result<ScheduleNode> group_node(const Action& group, const Prepared& prepared) const {
    if (const Param* p = atomic_param(prepared.params)) {
      return error(codes::mimic::misplaced_parameter, p->at,
                   "'" + p->name() + "' applies to atomic actions, not to a group");
    }
    return ScheduleNode::group(group.kind == Action::Kind::sequence ? Kind::sequence : Kind::parallel, prepared.timing,
                               location(group.at));
  }

  Result<ScheduleNode> instantiate(const Action& action, const Definition& macro, const ActionParams& params,
                                   const Timing& timing, const Context& body_context) {
    if (const Param* p = atomic_param(params)) {
      return error(codes::mimic::misplaced_parameter, p->at,
                   "'" + p->name() + "' does not apply to '" + macro.name +
                       "', a macro: give it alignment and blend parameters only");
    }
    if (action.has_list)
      return error(codes::mimic::macro_with_list, action.list_at,
                   "'" + macro.name + "' is a macro; it takes no time-value list");
    if (std::find(stack_.begin(), stack_.end(), macro.name) != stack_.end()) {
      std::string chain;
      for (const std::string& name : stack_) chain += name + " -> ";
      return error(codes::mimic::recursive_macro, action.at,
                   "the macro '" + macro.name + "' uses itself (" + chain + macro.name + ")");
    }
    stack_.push_back(macro.name);
    Result<ScheduleNode> body = build(macro.group, body_context);
    stack_.pop_back();
    if (!body) return body.error();
    body->timing = timing;  // the instance's alignment, applied as to a group
    return body;
  }

  Result<ScheduleNode> atomic(const Action& action, ActionParams params, Timing timing, BlendMode blend,
                              const Context& context) {
    Leaf leaf;
    leaf.at = action.at;
    leaf.blend = blend;
    const auto expression = expressions_.find(action.name);
    if (expression != expressions_.end()) {
      leaf.expression = true;
      leaf.first_target = static_cast<std::uint32_t>(targets_.size());
      if (params.value) {
        const algebra::FacialState amplified = algebra::amplify(expression->second, params.value->value);
        for (int fap = 3; fap <= kFapCount; ++fap) {
          if (expression->second.at(fap) == 0) continue;
          targets_.push_back({name_id(find_fap(fap)->name), static_cast<double>(amplified.at(fap))});
        }
      }
      leaf.target_count = static_cast<std::uint32_t>(targets_.size() - leaf.first_target);
    } else if (const std::uint32_t id = name_id(action.name); contributions(id).empty()) {
      return error(codes::profile::unknown_parameter, action.at, unknown_parameter_message(action.name, profile_));
    } else {
      leaf.first_target = id;
      leaf.target_count = 1;
    }
    if (action.has_list) {
      if (expression != expressions_.end()) {
        return error(codes::mimic::expression_with_list, action.list_at,
                     "'" + action.name + "' is an expression; fade it with <in=..., value=...>");
      }
      if (const Param* p = atomic_param(params)) {
        return error(codes::mimic::misplaced_parameter, p->at,
                     "'" + p->name() + "' does not apply to a time-value list");
      }
      if (auto checked = check_list(action); !checked) return checked.error();
      leaf.shape = Leaf::Shape::list;
      timing.duration = action.times.empty() ? 0 : action.times.back().value;
    } else if (params.first_fade && params.first_periodic) {
      const Param* later = params.first_fade->at.line > params.first_periodic->at.line ||
                                   (params.first_fade->at.line == params.first_periodic->at.line &&
                                    params.first_fade->at.column > params.first_periodic->at.column)
                               ? params.first_fade
                               : params.first_periodic;
      return error(codes::mimic::mixed_shapes, later->at,
                   "'" + later->name() +
                       "' mixes a fade (in, hold, out, value) with a "
                       "periodic action (min, max, freq, period, duration)");
    } else if (params.first_fade || expression != expressions_.end()) {
      if (params.first_periodic) {
        return error(codes::mimic::misplaced_parameter, params.first_periodic->at,
                     "'" + params.first_periodic->name() + "' does not apply to an expression fade");
      }
      if (!params.value)
        return error(codes::mimic::fade_without_value, action.at,
                     "a fade needs value=... (and in, hold, out as needed)");
      leaf.shape = Leaf::Shape::fade;
      timing.duration = value_or_zero(params.in) + value_or_zero(params.hold) + value_or_zero(params.out);
    } else if (params.first_periodic) {
      if (auto checked = check_periodic(action, params, context); !checked) return checked.error();
      leaf.shape = Leaf::Shape::periodic;
      if (params.duration) timing.duration = params.duration->value;
    } else {
      return error(codes::mimic::no_shape, action.at,
                   "'" + action.name +
                       "' needs a fade (in, hold, out, value), a periodic "
                       "function (min, max, freq or period) or a time-value list");
    }
    leaf.curve = curve_of(leaf.shape, params);
    if (leaf.shape == Leaf::Shape::list) {
      if (list_points_.size() + action.times.size() > UINT32_MAX) return too_many_actions(action);
      leaf.first_point = static_cast<std::uint32_t>(list_points_.size());
      leaf.point_count = static_cast<std::uint32_t>(action.times.size());
      for (std::size_t i = 0; i < action.times.size(); ++i) {
        list_points_.push_back({action.times[i].value, action.values[i].value});
      }
    }
    check_ranges(leaf, params, action);
    leaves_.push_back(leaf);
    return ScheduleNode::leaf(leaves_.size() - 1, timing, location(action.at));
  }

  static double value_or_zero(const std::optional<Number>& n) { return n ? n->value : 0; }

  static decltype(Leaf::curve) curve_of(Leaf::Shape shape, const ActionParams& p) {
    if (shape == Leaf::Shape::fade) {
      Fade fade;
      fade.in = value_or_zero(p.in);
      fade.hold = value_or_zero(p.hold);
      fade.out = value_or_zero(p.out);
      fade.value = value_or_zero(p.value);
      fade.interpolation = p.interpolation();
      if (p.connect && p.connect->value) {
        fade.connect = Fade::Connect::given;
        fade.connect_to = p.connect->value->value;
      } else if (p.connect) {
        fade.connect = Fade::Connect::next;
      }
      return fade;
    }
    if (shape == Leaf::Shape::periodic) {
      Periodic wave;  // unscaled: each target scales it by its factor
      wave.shape =
          p.function && p.function->id == ParamName::linear ? Periodic::Shape::triangle : Periodic::Shape::sine;
      wave.min = value_or_zero(p.min);
      wave.max = p.max->value;
      wave.period = p.period ? p.period->value : 1 / p.freq->value;
      return wave;
    }
    return std::monostate{};
  }

  Target target(const Leaf& leaf, std::uint32_t i) const {
    return leaf.expression ? targets_[leaf.first_target + i] : Target{leaf.first_target, 1};
  }

  Status check_list(const Action& action) const {
    if (action.times.size() != action.values.size()) {
      return error(codes::mimic::list_length, action.list_at,
                   std::to_string(action.times.size()) + " times but " + std::to_string(action.values.size()) +
                       " values: a time-value list needs one value per time");
    }
    for (std::size_t i = 0; i < action.times.size(); ++i) {
      const Number& t = action.times[i];
      if (t.value < 0)
        return error(codes::mimic::list_time, t.at,
                     "times are offsets from the action's start and must not be negative");
      if (i > 0 && t.value < action.times[i - 1].value) {
        return error(codes::mimic::list_time, t.at,
                     "time " + format_number(t.value) + " comes before the previous time " +
                         format_number(action.times[i - 1].value) + ": times must not decrease");
      }
    }
    return ok_status();
  }

  Status check_periodic(const Action& action, const ActionParams& p, const Context& context) const {
    if (!p.freq && !p.period)
      return error(codes::mimic::periodic_incomplete, action.at, "a periodic action needs freq=... or period=...");
    if (p.freq && p.period && std::abs(p.freq->value * p.period->value - 1) > 1e-9) {
      return error(codes::mimic::parameter_conflict, p.period->at,
                   "freq=" + format_number(p.freq->value) + " and period=" + format_number(p.period->value) +
                       " disagree (freq x period must be 1)");
    }
    if (!p.max)
      return error(codes::mimic::periodic_incomplete, action.at, "a periodic action needs max=... (min defaults to 0)");
    if (p.function && p.function->id != ParamName::sin && p.function->id != ParamName::linear) {
      return error(codes::mimic::bad_function, p.function->at,
                   "a periodic action oscillates with sin or linear, not " + p.function->name());
    }
    if (!p.duration && context.parent != Action::Kind::parallel) {
      return error(codes::mimic::periodic_without_length, action.at,
                   "a periodic action without duration= must be in a parallel, which gives its length");
    }
    return ok_status();
  }

  // Values beyond what the target can carry: a warning at the number (docs/mimic.md,
  // "Timing and values").
  void check_ranges(const Leaf& leaf, const ActionParams& params, const Action& action) {
    std::vector<const Number*> numbers;
    for (const std::optional<Number>* n : {&params.value, &params.min, &params.max}) {
      if (*n) numbers.push_back(&**n);
    }

    for (const Number& v : action.values) numbers.push_back(&v);
    for (std::uint32_t t = 0; t < leaf.target_count; ++t) {
      const Target target = this->target(leaf, t);
      for (const FapContribution& c : contributions(target.name)) {
        const int high = c.fap <= 2 ? 63 : find_fap(c.fap)->legal_max();
        const int low = c.fap <= 2 ? 0 : -high;
        for (const Number* n : numbers) {
          // An expression's factor already includes the fade's value: check the factor alone.
          const double written = leaf.expression ? 1 : n->value;
          const double fap_value = written * target.factor * c.scale;
          if (fap_value >= low && fap_value <= high) continue;
          warnings_.push_back(make_warning(
              codes::mimic::out_of_range, location(n->at),
              "value " + format_number(n->value) + " of '" + names_[target.name] + "' is " + format_number(fap_value) +
                  " in " + std::string(find_fap(c.fap)->name) + " units, outside " + std::to_string(low) + ".." +
                  std::to_string(high) + " (it will be clamped)",
              source_line(source_, n->at.line)));
        }
      }
    }
  }

  // ---- lowering ------------------------------------------------------------------------------

  // Whether a run of the leaf makes clips (one per target): not when it has no target, no points,
  // or nothing left of its span.
  bool makes_clips(const Leaf& leaf, const Occurrence& o) const {
    if (leaf.target_count == 0) return false;
    double begin = o.begin;
    if (leaf.shape == Leaf::Shape::list) {
      if (leaf.point_count == 0) return false;
      begin += list_points_[leaf.first_point].time;  // the curve starts at the first time
    }
    return o.end > begin;
  }

  // The frame budget against the timeline's end before the clips are made: the end and the source
  // that Timeline::end() and FrameStream::start find among the clips (the last clip that ends
  // last; clips come in the order of the runs).
  Status check_length(const Schedule& scheduled) const {
    double end = 0;
    const Leaf* last = nullptr;
    for (const Occurrence& o : scheduled.occurrences) {
      const Leaf& leaf = leaves_[o.leaf_id];
      if (!makes_clips(leaf, o) || (last && o.end < end)) continue;
      end = o.end;
      last = &leaf;
    }
    end = std::max(end, 0.0);
    if (!options_.frames.exceeded_by(end)) return ok_status();
    return frame_budget_error(end, last ? location(last->at) : Location{}, options_.frames);
  }

  Timeline lower(const Schedule& scheduled) {
    Timeline timeline;
    std::size_t clips = 0;  // at most one per occurrence and target: no growth by doubling
    for (const Occurrence& o : scheduled.occurrences) clips += leaves_[o.leaf_id].target_count;
    timeline.clips.reserve(clips);
    clip_names_.reserve(clips);
    // Runs come in tree order, as the leaves were made: each leaf is let go once its runs are
    // lowered, so that the leaves shrink as the clips grow. (A Mimic leaf runs once: no repeats.)
    const bool in_leaf_order =
        std::is_sorted(scheduled.occurrences.begin(), scheduled.occurrences.end(),
                       [](const Occurrence& a, const Occurrence& b) { return a.leaf_id < b.leaf_id; });
    for (const Occurrence& o : scheduled.occurrences) {
      if (in_leaf_order) leaves_.release_before(o.leaf_id);
      const Leaf& leaf = leaves_[o.leaf_id];
      if (!makes_clips(leaf, o)) continue;
      for (std::uint32_t t = 0; t < leaf.target_count; ++t) add_clip(timeline, leaf, target(leaf, t), o);
    }
    leaves_ = {};
    resolve_connects(timeline);
    return timeline;
  }

  void add_clip(Timeline& timeline, const Leaf& leaf, const Target& target, const Occurrence& o) {
    Clip clip;
    clip.target = names_[target.name];
    clip.begin = o.begin;
    clip.end = o.end;
    clip.blend = leaf.blend;
    clip.source = location(leaf.at);
    const Fade* fade = std::get_if<Fade>(&leaf.curve);
    switch (leaf.shape) {
      case Leaf::Shape::fade: {
        const double in = fade->in;
        const double hold = fade->hold;
        const double out = fade->out;
        const double v = leaf.expression ? target.factor : fade->value * target.factor;
        const Interpolation f = fade->interpolation;
        // Rise from the neutral 0 to v, hold, fall to the end value (0 until `connect` sets it).
        clip.curve.keys = {{0, 0, f}, {in, v, Interpolation::linear}, {in + hold, v, f}, {in + hold + out, 0}};
        break;
      }
      case Leaf::Shape::periodic: {
        Periodic wave = std::get<Periodic>(leaf.curve);
        wave.min *= target.factor;
        wave.max *= target.factor;
        clip.curve.periodic = wave;
        break;
      }
      case Leaf::Shape::list: {
        const ListPoint& first = list_points_[leaf.first_point];
        // The curve starts at the first time: before it the action is absent.
        clip.begin = o.begin + first.time;
        clip.curve.keys.reserve(leaf.point_count);
        for (std::size_t i = leaf.first_point; i < leaf.first_point + leaf.point_count; ++i) {
          const ListPoint& point = list_points_[i];
          clip.curve.keys.push_back(KeyPoint{point.time - first.time, point.value * target.factor});
        }
        break;
      }
    }
    if (fade && fade->connect != Fade::Connect::none) {
      connecting_.push_back({timeline.clips.size(), fade->connect == Fade::Connect::given, fade->connect_to});
    }
    timeline.clips.push_back(std::move(clip));
    clip_names_.push_back(target.name);
  }

  // connect: the fade ends at the value the same target's next clip (the first beginning at or
  // after this one's end) has at its own begin; or at connect=x when given. Targets are taken in
  // the order of their names, and each target's clips in the order they begin.
  void resolve_connects(Timeline& timeline) {
    if (connecting_.empty()) return;
    std::vector<std::uint32_t> connects(timeline.clips.size(), kNoConnect);  // index into connecting_
    std::vector<bool> wanted(names_.size(), false);
    for (std::size_t c = 0; c < connecting_.size(); ++c) {
      connects[connecting_[c].clip] = static_cast<std::uint32_t>(c);
      wanted[clip_names_[connecting_[c].clip]] = true;
    }
    std::vector<std::vector<std::size_t>> by_target(names_.size());  // only the targets that connect
    for (std::size_t i = 0; i < timeline.clips.size(); ++i) {
      if (wanted[clip_names_[i]]) by_target[clip_names_[i]].push_back(i);
    }
    std::vector<std::uint32_t>().swap(clip_names_);  // `= {}` would keep the capacity
    std::vector<std::uint32_t> in_name_order;
    for (std::uint32_t id = 0; id < names_.size(); ++id) {
      if (wanted[id]) in_name_order.push_back(id);
    }
    std::sort(in_name_order.begin(), in_name_order.end(),
              [&](std::uint32_t a, std::uint32_t b) { return names_[a] < names_[b]; });
    for (const std::uint32_t id : in_name_order) {
      std::vector<std::size_t>& indices = by_target[id];
      const auto by_begin = [&](std::size_t a, std::size_t b) {
        return timeline.clips[a].begin < timeline.clips[b].begin;
      };
      // Clips come in schedule order, mostly already by begin: sorting them again costs a merge sort.
      if (!std::is_sorted(indices.begin(), indices.end(), by_begin)) {
        std::stable_sort(indices.begin(), indices.end(), by_begin);
      }
      for (const std::size_t i : indices) {
        if (connects[i] == kNoConnect) continue;
        const Connecting& connect = connecting_[connects[i]];
        Clip& clip = timeline.clips[i];
        double end_value = 0;
        if (connect.given) {
          end_value = connect.to;
        } else {
          const auto next = std::lower_bound(indices.begin(), indices.end(), clip.end,
                                             [&](std::size_t c, double t) { return timeline.clips[c].begin < t; });
          if (next != indices.end()) {
            const Clip& following = timeline.clips[*next];
            end_value = following.curve.value_at(following.curve_offset);
          }
        }
        clip.curve.keys.back().value = end_value;
      }
      std::vector<std::size_t>().swap(indices);  // `= {}` would keep the capacity
    }
  }
};

}  // namespace
}  // namespace mimic

Result<MimicProgram> compile_mimic(std::string_view source, const std::string& file_name,
                                   const ReaderOptions& options) {
  return mimic::Compiler(source, file_name, options).run();
}

}  // namespace fapc
