// The scheduler (docs/timeline.md). Two passes: measure_all() finds each node's active duration
// where it is known without the parent, bottom-up, into a table by the node's number in depth-first
// order (so the whole run is linear in the tree size, with no map from nodes), then place() walks
// the tree once, top-down, with absolute times, numbering the nodes the same way.
#include "fapc/timeline/schedule.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "fapc/timeline/codes.hpp"

namespace fapc::timeline {
namespace {

using Kind = ScheduleNode::Kind;
constexpr double kForever = std::numeric_limits<double>::infinity();
// 63 years: beyond what --max-frames allows at any frame rate (2^30 frames at 1 fps is 34 years).
constexpr double kLatestTime = 2e9;

std::string seconds(double t) {
  std::ostringstream out;
  out << t << " s";
  return out.str();
}

class Scheduler {
 public:
  std::optional<ScheduleError> error;
  std::int64_t max_runs = 0;
  std::size_t leaves = 0;  // counted by measure_tree(): as many runs as a tree without repeats has
  // And the runs its repeat counts promise (each leaf once per iteration of it and of each
  // ancestor; an indefinite repeat counted once): an estimate, for reserving.
  double promised_runs = 0;

  // Numbers the nodes (depth first, the root 0) and measures each: before place().
  void measure_tree(const ScheduleNode& root) {
    const std::size_t nodes = count(root, 1);
    measured_.assign(nodes, std::nullopt);
    size_.assign(nodes, 0);
    measure_all(root, 0);
  }

  // Places `node` (number `index`) with its active span starting at `start`. `limit` is the
  // reference end that open-ended nodes stretch to; `cut` is where the ancestors end. Returns the
  // node's active end.
  double place(const ScheduleNode& node, std::size_t index, double start, std::optional<double> limit, double cut,
               std::vector<Occurrence>& out) {
    if (error) return start;
    std::optional<double> active = measured_[index];
    if (!active && limit) active = std::max(0.0, *limit - start);
    if (node.kind == Kind::leaf) {
      if (!active) {
        fail(node, ScheduleProblem::no_duration,
             "has no duration and nothing around it ends: give it a duration, or place it "
             "in a parallel with a known end");
        return start;
      }
      if (start < 0) {
        fail(node, ScheduleProblem::starts_before_zero, "starts before time 0 (at " + seconds(start) + ")");
        return start;
      }
      // Far out, a double cannot tell a run's end from its begin (1e300 + 3 == 1e300) and the run
      // would vanish without a word; no renderable animation gets near (docs/security.md).
      if (start + *active > kLatestTime) {
        fail(node, ScheduleProblem::ends_too_late,
             "ends at " + seconds(start + *active) + ", after the latest time fapc schedules (" + seconds(kLatestTime) +
                 ")");
        return start;
      }
      const double simple = node.timing.duration.value_or(*active);
      place_runs(node, start, simple, *active, std::min(cut, start + *active), out);
      return start + *active;
    }
    if (!active && node.timing.repeat_indefinite) {
      // Repeating without end would never stop laying out iterations.
      fail(node, ScheduleProblem::endless_repeat,
           "repeats indefinitely and nothing around it ends: give it or a parent an end");
      return start;
    }
    // A group: lay out one iteration, then repeat its occurrences shifted. A group of unknown
    // length with nothing around it to end it still places its children: the open one among
    // them reports the error at its own position.
    const double inner_cut = active ? std::min(cut, start + *active) : cut;
    const std::size_t first = out.size();
    const std::optional<double> own_limit =
        node.timing.duration ? std::optional<double>(start + *node.timing.duration) : limit;
    // With an explicit duration, children beyond it are cut at the end of each iteration.
    const double iteration_cut = node.timing.duration ? std::min(inner_cut, start + *node.timing.duration) : inner_cut;
    const double children_end = place_children(node, index, start, own_limit, iteration_cut, out);
    if (error) return start;
    const double simple = node.timing.duration.value_or(children_end - start);
    // Iterations stop at the repeat count (and repeatDur) even when the group's length was only
    // known once its children were placed: a group that does not repeat is laid out once.
    double repeat_end = inner_cut;
    if (!node.timing.repeat_indefinite) repeat_end = std::min(repeat_end, start + simple * node.timing.repeat);
    if (node.timing.repeat_duration) repeat_end = std::min(repeat_end, start + *node.timing.repeat_duration);
    repeat_group(node, first, start, simple, repeat_end, out);
    return active ? start + *active : children_end;
  }

 private:
  // By node number: the active duration when known without a parent end; the subtree's size.
  std::vector<OptionalSeconds> measured_;  // 8 bytes a node, not 16
  std::vector<std::size_t> size_;

  std::size_t count(const ScheduleNode& node, double iterations) {
    if (!node.timing.repeat_indefinite) iterations *= std::max(1.0, std::ceil(node.timing.repeat));
    if (node.kind == Kind::leaf) {
      ++leaves;
      promised_runs += iterations;
    }
    std::size_t n = 1;
    for (const ScheduleNode& child : node.children) n += count(child, iterations);
    return n;
  }

  // Measures the subtree of `node` (number `index`), children first; returns its size.
  std::size_t measure_all(const ScheduleNode& node, std::size_t index) {
    std::size_t next = index + 1;
    for (const ScheduleNode& child : node.children) next += measure_all(child, next);
    size_[index] = next - index;
    measured_[index] = active_duration(node, simple_duration(node, index));
    return size_[index];
  }

  // Calls `visit(child, its number)` for each child of node `index`, in order.
  template <class Visit>
  void for_each_child(const ScheduleNode& node, std::size_t index, Visit visit) const {
    std::size_t child_index = index + 1;
    for (const ScheduleNode& child : node.children) {
      visit(child, child_index);
      child_index += size_[child_index];
    }
  }

  // Repeats of repeats can ask for more runs than memory holds (an indefinite repeat of a tiny
  // group beside a very long sibling): past max_runs the schedule is an error at the node.
  bool too_many(const ScheduleNode& node, const std::vector<Occurrence>& out) {
    if (static_cast<std::int64_t>(out.size()) < max_runs) return error.has_value();
    // The predicate is the limit's own wording: the limit, its value and the option raising it.
    Limits limits;
    limits.max_runs = max_runs;
    fail(node, ScheduleProblem::too_many_runs,
         limit_error(node.source, "repeats to too many runs", Limit::runs, limits).message);
    return true;
  }

  void fail(const ScheduleNode& node, ScheduleProblem problem, std::string predicate) {
    if (!error) error = ScheduleError{problem, node.tag, node.source, std::move(predicate)};
  }

  std::optional<double> simple_duration(const ScheduleNode& node, std::size_t index) {
    if (node.timing.duration) return node.timing.duration;
    switch (node.kind) {
      case Kind::leaf:
        return std::nullopt;
      case Kind::sequence:
        return measure_sequence(node, index);
      case Kind::parallel:
      case Kind::exclusive:
        return measure_parallel(node, index);
    }
    return std::nullopt;
  }

  std::optional<double> active_duration(const ScheduleNode& node, std::optional<double> simple) {
    const Timing& timing = node.timing;
    if (timing.end) return std::max(0.0, *timing.end - timing.offset);
    if (timing.repeat_indefinite) return timing.repeat_duration;
    if (!simple) return std::nullopt;
    double active = *simple * timing.repeat;
    if (timing.repeat_duration) active = std::min(active, *timing.repeat_duration);
    return active;
  }

  std::optional<double> measure_sequence(const ScheduleNode& node, std::size_t index) {
    double cursor = 0;
    double latest = 0;
    bool known = true;
    for_each_child(node, index, [&](const ScheduleNode& child, std::size_t child_index) {
      const std::optional<double> active = measured_[child_index];
      if (!known || !active) {
        known = false;
        return;
      }
      cursor = cursor + child.timing.offset + *active;
      latest = std::max(latest, cursor);
    });
    if (!known) return std::nullopt;
    return latest;
  }

  // A parallel's reference end is the latest end among the children whose duration is known
  // without it (right-aligned children excluded: their place depends on it).
  std::optional<double> reference_end(const ScheduleNode& node, std::size_t index) {
    std::optional<double> reference;
    for_each_child(node, index, [&](const ScheduleNode& child, std::size_t child_index) {
      if (child.timing.align_right) return;
      if (const std::optional<double> active = measured_[child_index]) {
        reference = std::max(reference.value_or(-kForever), child.timing.offset + *active);
      }
    });
    return reference;
  }

  std::optional<double> measure_parallel(const ScheduleNode& node, std::size_t index) {
    // An empty par or excl (or an excl whose event picked no branch) lasts 0 s (SMIL).
    if (node.children.empty()) return 0.0;
    const std::optional<double> reference = reference_end(node, index);
    if (!reference) return std::nullopt;
    double latest = std::max(0.0, *reference);
    for (const ScheduleNode& child : node.children) {
      if (child.timing.align_right) latest = std::max(latest, *reference + *child.timing.align_right);
    }
    return latest;
  }

  void place_runs(const ScheduleNode& node, double start, double simple, double active, double cut,
                  std::vector<Occurrence>& out) {
    const std::size_t leaf = node.leaf_id;
    // A leaf wholly after the end of an ancestor (a group's dur, --duration) does not run.
    if (start > cut || (start == cut && simple > 0)) return;
    if (simple <= 0) {
      out.push_back(Occurrence{leaf, start, 0, start, 0, 0});
      return;
    }
    const double active_end = std::min(start + active, cut);
    for (int i = 0;; ++i) {
      const double begin = start + i * simple;
      if (begin >= active_end || too_many(node, out)) break;
      out.push_back(Occurrence{leaf, begin, simple, std::min(begin + simple, active_end), 0, i});
    }
  }

  // Places the children of a group starting at `start`; returns the latest child end.
  double place_children(const ScheduleNode& node, std::size_t index, double start, std::optional<double> limit,
                        double cut, std::vector<Occurrence>& out) {
    if (node.kind == Kind::sequence) return place_sequence(node, index, start, limit, cut, out);
    std::optional<double> reference;
    if (node.timing.duration) {
      reference = start + *node.timing.duration;
    } else if (const std::optional<double> relative = reference_end(node, index)) {
      reference = start + *relative;
    } else {
      reference = limit;
    }
    double latest = start;
    std::vector<ChildRun> runs;  // exclusive groups: who cuts whom
    std::size_t child_index = index + 1;
    for (const ScheduleNode& child : node.children) {
      const std::size_t this_index = child_index;
      child_index += size_[this_index];
      double child_start = start + child.timing.offset;
      std::optional<double> child_limit = reference;
      if (child.timing.align_right) {
        if (!reference) {
          fail(child, ScheduleProblem::right_without_end, "is aligned right but the parallel has no known end");
          return latest;
        }
        const double child_end = *reference + *child.timing.align_right;
        // A child of known length moves so that it ends there; an open-ended one stretches to it.
        if (const std::optional<double> active = measured_[this_index]) child_start = child_end - *active;
        child_limit = child_end;
      }
      const std::size_t from = out.size();
      latest = std::max(latest, place(child, this_index, child_start, child_limit, cut, out));
      if (error) return latest;
      if (node.kind == Kind::exclusive) runs.push_back(ChildRun{child_start, from, out.size()});
    }
    if (node.kind == Kind::exclusive) cut_exclusive(runs, out);
    return latest;
  }

  double place_sequence(const ScheduleNode& node, std::size_t index, double start, std::optional<double> limit,
                        double cut, std::vector<Occurrence>& out) {
    double cursor = start;
    double latest = start;
    std::size_t child_index = index + 1;
    for (const ScheduleNode& child : node.children) {
      const std::size_t this_index = child_index;
      child_index += size_[this_index];
      if (child.timing.align_right) {
        fail(child, ScheduleProblem::right_in_sequence,
             "right alignment is only allowed in a parallel, not in a sequence");
        return latest;
      }
      cursor = place(child, this_index, cursor + child.timing.offset, limit, cut, out);
      if (error) return latest;
      latest = std::max(latest, cursor);
    }
    return latest;
  }

  struct ChildRun {
    double start;
    std::size_t from, to;  // its occurrences in `out`
  };

  // In an exclusive group one child plays at a time: a child that starts cuts the one playing
  // (at equal starts the later child in the source wins).
  static void cut_exclusive(std::vector<ChildRun> runs, std::vector<Occurrence>& out) {
    std::stable_sort(runs.begin(), runs.end(), [](const ChildRun& a, const ChildRun& b) { return a.start < b.start; });
    for (std::size_t i = 0; i + 1 < runs.size(); ++i) {
      for (std::size_t k = runs[i].from; k < runs[i].to; ++k) {
        out[k].end = std::max(out[k].begin, std::min(out[k].end, runs[i + 1].start));
      }
    }
  }

  void repeat_group(const ScheduleNode& node, std::size_t first, double start, double simple, double cut,
                    std::vector<Occurrence>& out) {
    const std::size_t last = out.size();
    if (simple <= 0) return;
    for (int i = 1; start + i * simple < cut && !too_many(node, out); ++i) {
      const double shift = i * simple;
      for (std::size_t k = first; k < last; ++k) {
        Occurrence copy = out[k];
        copy.begin += shift;
        copy.end = std::min(copy.end + shift, cut);
        if (copy.begin >= cut) continue;
        out.push_back(copy);
      }
    }
  }
};

}  // namespace

ScheduleNode ScheduleNode::leaf(std::size_t id, Timing timing, Location source) {
  ScheduleNode node;
  node.kind = Kind::leaf;
  node.timing = timing;
  node.leaf_id = id;
  node.source = std::move(source);
  return node;
}

ScheduleNode ScheduleNode::group(Kind kind, Timing timing, Location source) {
  ScheduleNode node;
  node.kind = kind;
  node.timing = timing;
  node.source = std::move(source);
  return node;
}

namespace {

// Each problem's code (codes.def): a user mends each differently.
ErrorCode schedule_code(ScheduleProblem problem) {
  switch (problem) {
    case ScheduleProblem::no_duration:
      return codes::timeline::no_duration;
    case ScheduleProblem::starts_before_zero:
      return codes::timeline::starts_before_zero;
    case ScheduleProblem::ends_too_late:
      return codes::timeline::ends_too_late;
    case ScheduleProblem::endless_repeat:
      return codes::timeline::endless_repeat;
    case ScheduleProblem::too_many_runs:
      return codes::limit::runs;
    case ScheduleProblem::right_without_end:
      return codes::timeline::right_without_end;
    case ScheduleProblem::right_in_sequence:
      return codes::timeline::right_in_sequence;
  }
  return codes::timeline::no_duration;
}

}  // namespace

Diagnostic ScheduleError::diagnostic(std::string_view subject) const {
  std::string message = subject.empty() ? predicate : std::string(subject) + ' ' + predicate;
  return make_error(schedule_code(problem), where, std::move(message));
}

Result<Schedule> schedule(const ScheduleNode& root, const ScheduleOptions& options) {
  auto scheduled = schedule_tree(root, options);
  if (auto* problem = std::get_if<ScheduleError>(&scheduled)) {
    // Only a start and an end read wrong without a subject ("starts before time 0").
    const bool needs_subject =
        problem->problem == ScheduleProblem::starts_before_zero || problem->problem == ScheduleProblem::ends_too_late;
    return problem->diagnostic(needs_subject ? "the action" : "");
  }
  return std::get<Schedule>(std::move(scheduled));
}

std::variant<Schedule, ScheduleError> schedule_tree(const ScheduleNode& root, const ScheduleOptions& options) {
  Scheduler scheduler;
  scheduler.max_runs = options.max_runs;
  Schedule result;
  const double cut = options.root_end.value_or(kForever);
  scheduler.measure_tree(root);
  // Room for the runs the repeat counts promise up front: a million runs grown by doubling held
  // 1.5 times their size at the end, and both the old and the new block while the last copy was
  // made (96 MB at issue 19's 10^6-element XMT-Omega script). Runs cut short leave room unused,
  // which costs address space, not memory (pages never written are never given); the room stays
  // within the run limit and a few times the tree, which is in memory already.
  const double room =
      std::min({scheduler.promised_runs, static_cast<double>(std::max<std::int64_t>(options.max_runs, 0)),
                8.0 * static_cast<double>(scheduler.leaves)});
  result.occurrences.reserve(static_cast<std::size_t>(room));
  result.end = scheduler.place(root, 0, root.timing.offset, options.root_end, cut, result.occurrences);
  if (scheduler.error) return *scheduler.error;
  if (options.root_end) result.end = *options.root_end;
  return result;
}

}  // namespace fapc::timeline
