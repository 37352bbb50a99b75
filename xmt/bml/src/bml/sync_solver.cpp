#include "bml/sync_solver.hpp"

#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>

namespace fapc::bml {
namespace {

constexpr double kTolerance = 1e-6;  // seconds: below a sample at 96 kHz
constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();

// The points as variables: behaviour b's point p is base[b] + p; the block's start is the last.
struct Variables {
  std::vector<std::uint32_t> base;
  std::uint32_t zero = 0;

  explicit Variables(const std::vector<SolverBehaviour>& behaviours) {
    base.reserve(behaviours.size() + 1);
    std::uint32_t next = 0;
    for (const SolverBehaviour& b : behaviours) {
      base.push_back(next);
      next += kStandardPoints + static_cast<std::uint32_t>(b.marks.size());
    }
    base.push_back(next);
    zero = next;
  }
  std::uint32_t of(const PointRef& p) const { return base[p.behaviour] + p.point; }
  std::uint32_t count() const { return zero + 1; }
};

double default_offset(const SolverBehaviour& b, std::uint32_t point) {
  return point < kStandardPoints ? b.defaults[point] : b.marks[point - kStandardPoints];
}

// Weighted union-find: time(v) = time(find(v)) + offset(v) once paths are compressed.
class Classes {
 public:
  explicit Classes(std::uint32_t n) : parent_(n), offset_(n, 0.0), rank_(n, 0) {
    for (std::uint32_t v = 0; v < n; ++v) parent_[v] = v;
  }
  std::uint32_t find(std::uint32_t v) {
    std::uint32_t root = v;
    double total = 0;
    while (parent_[root] != root) {
      total += offset_[root];
      root = parent_[root];
    }
    // Compress: every node on the path points at the root with its whole offset.
    while (parent_[v] != root) {
      const std::uint32_t next = parent_[v];
      const double own = offset_[v];
      parent_[v] = root;
      offset_[v] = total;
      total -= own;
      v = next;
    }
    return root;
  }
  double offset(std::uint32_t v) {
    find(v);
    return offset_[v];
  }
  // time(a) = time(b) + d, for a and b in different classes.
  void join(std::uint32_t a, std::uint32_t b, double d) {
    const std::uint32_t ra = find(a);
    const std::uint32_t rb = find(b);
    // time(ra) = time(a) - off(a) = time(b) + d - off(a) = time(rb) + off(b) + d - off(a)
    const double ra_from_rb = offset_[b] + d - offset_[a];
    if (ra == a || rank_[ra] <= rank_[rb]) {
      parent_[ra] = rb;
      offset_[ra] = ra_from_rb;
      if (rank_[ra] == rank_[rb]) ++rank_[rb];
    } else {
      parent_[rb] = ra;
      offset_[rb] = -ra_from_rb;
    }
  }

 private:
  std::vector<std::uint32_t> parent_;
  std::vector<double> offset_;
  std::vector<std::uint8_t> rank_;
};

// The equalities accepted so far, for naming the chain behind a contradiction: adjacency lists
// threaded through one array (a vector per point cost an allocation per point).
class Edges {
 public:
  explicit Edges(std::uint32_t n) : first_(n, kNone) {}
  void add(std::uint32_t a, std::uint32_t b, int label) {
    link(a, b, label);
    link(b, a, label);
  }
  // The labels on the path from `from` to `to` (both in one class), in order.
  std::vector<int> chain(std::uint32_t from, std::uint32_t to) const {
    std::vector<std::uint32_t> came_from(first_.size(), kNone);
    std::vector<int> via(first_.size(), -1);
    std::deque<std::uint32_t> queue{from};
    came_from[from] = from;
    while (!queue.empty() && came_from[to] == kNone) {
      const std::uint32_t v = queue.front();
      queue.pop_front();
      for (std::uint32_t e = first_[v]; e != kNone; e = entries_[e].next)
        if (came_from[entries_[e].to] == kNone) {
          came_from[entries_[e].to] = v;
          via[entries_[e].to] = entries_[e].label;
          queue.push_back(entries_[e].to);
        }
    }
    std::vector<int> out;
    if (came_from[to] == kNone) return out;
    for (std::uint32_t v = to; v != from; v = came_from[v])
      if (out.empty() || out.back() != via[v]) out.push_back(via[v]);
    std::reverse(out.begin(), out.end());
    return out;
  }

 private:
  struct Entry {
    std::uint32_t to;
    std::uint32_t next;
    int label;
  };
  std::vector<std::uint32_t> first_;
  std::vector<Entry> entries_;
  void link(std::uint32_t a, std::uint32_t b, int label) {
    entries_.push_back({b, first_[a], label});
    first_[a] = static_cast<std::uint32_t>(entries_.size() - 1);
  }
};

class Solver {
 public:
  Solver(const std::vector<SolverBehaviour>& behaviours, const std::vector<Relation>& relations)
      : behaviours_(behaviours),
        relations_(relations),
        vars_(behaviours),
        classes_(vars_.count()),
        edges_(vars_.count()),
        named_(vars_.count(), 0),
        first_label_(vars_.count(), -1) {}

  Solved run() {
    Solved out;
    if (auto error = join_all()) {
      out.error = std::move(error);
      return out;
    }
    place();
    if (auto error = apply_inequalities()) {
      out.error = std::move(error);
      return out;
    }
    if (auto error = fill(out.solution)) out.error = std::move(error);
    return out;
  }

 private:
  const std::vector<SolverBehaviour>& behaviours_;
  const std::vector<Relation>& relations_;
  Variables vars_;
  Classes classes_;
  Edges edges_;
  std::vector<std::uint8_t> named_;  // the point appears in a relation (or is a rigid behaviour's)
  std::vector<int> first_label_;     // the first relation that named the point
  // Per class root: its time once placed, and the group (connected classes) it was placed with.
  std::vector<double> class_time_;
  std::vector<std::uint32_t> group_of_;
  std::vector<double> group_shift_;
  std::vector<std::uint8_t> group_free_;  // not tied to the block's start

  std::optional<SolveError> equate(std::uint32_t a, std::uint32_t b, double d, int label) {
    if (classes_.find(a) == classes_.find(b)) {
      const double have = classes_.offset(a) - classes_.offset(b);
      if (std::abs(have - d) <= kTolerance) return std::nullopt;
      SolveError e;
      e.what = SolveError::What::contradiction;
      e.label = label;
      e.chain = edges_.chain(b, a);
      e.time = d;
      e.other_time = have;
      e.absolute = b == vars_.zero;
      return e;
    }
    classes_.join(a, b, d);
    edges_.add(a, b, label);
    return std::nullopt;
  }

  void name(std::uint32_t v, int label) {
    named_[v] = 1;
    if (first_label_[v] < 0) first_label_[v] = label;
  }

  std::optional<SolveError> join_all() {
    // A rigid behaviour's points first: a constraint that disagrees with its own timing is the
    // one named.
    for (std::uint32_t b = 0; b < behaviours_.size(); ++b) {
      const SolverBehaviour& beh = behaviours_[b];
      if (!beh.rigid) continue;
      const std::uint32_t start = vars_.base[b];
      const std::uint32_t points = kStandardPoints + static_cast<std::uint32_t>(beh.marks.size());
      for (std::uint32_t p = 1; p < points; ++p) {
        if (auto e = equate(start + p, start, default_offset(beh, p), beh.own_label)) return e;
      }
    }
    for (const Relation& r : relations_) {
      if (r.kind != Relation::Kind::equal) continue;
      const std::uint32_t a = vars_.of(r.a);
      const std::uint32_t b = r.b ? vars_.of(*r.b) : vars_.zero;
      name(a, r.label);
      if (r.b) name(b, r.label);
      if (auto e = equate(a, b, r.offset, r.label)) return e;
    }
    for (const Relation& r : relations_) {
      if (r.kind != Relation::Kind::at_least) continue;
      name(vars_.of(r.a), r.label);
      if (r.b) name(vars_.of(*r.b), r.label);
    }
    return std::nullopt;
  }

  // The points of b that place it: its start, and every point a relation names.
  template <class Visit>
  void for_each_placing_point(std::uint32_t b, Visit visit) {
    const SolverBehaviour& beh = behaviours_[b];
    const std::uint32_t points = kStandardPoints + static_cast<std::uint32_t>(beh.marks.size());
    for (std::uint32_t p = 0; p < points; ++p)
      if (p == kStart || named_[vars_.base[b] + p]) visit(p);
  }

  double time_of(std::uint32_t v) {
    const std::uint32_t root = classes_.find(v);
    return class_time_[root] + group_shift_[group_of_[root]] + classes_.offset(v);
  }

  // Breadth first from the block's start, then from each group still unplaced: a behaviour puts
  // its unplaced classes at its default offsets from a placed one.
  void place() {
    const std::uint32_t n = vars_.count();
    class_time_.assign(n, 0.0);
    group_of_.assign(n, kNone);
    // Which behaviours touch each class root (through their placing points).
    std::vector<std::uint32_t> first(n + 1, 0);
    std::vector<std::uint32_t> touching;
    for (std::uint32_t b = 0; b < behaviours_.size(); ++b)
      for_each_placing_point(b, [&](std::uint32_t p) { ++first[classes_.find(vars_.base[b] + p) + 1]; });
    for (std::uint32_t v = 0; v < n; ++v) first[v + 1] += first[v];
    touching.resize(first[n]);
    std::vector<std::uint32_t> fill_at(first.begin(), first.end() - 1);
    for (std::uint32_t b = 0; b < behaviours_.size(); ++b)
      for_each_placing_point(b, [&](std::uint32_t p) {
        std::uint32_t& slot = fill_at[classes_.find(vars_.base[b] + p)];
        if (slot == first[classes_.find(vars_.base[b] + p)] || touching[slot - 1] != b) touching[slot++] = b;
      });
    std::vector<std::uint32_t> end_of(fill_at);
    std::vector<std::uint8_t> behaviour_done(behaviours_.size(), 0);

    const auto spread = [&](std::uint32_t seed, std::uint32_t group) {
      std::deque<std::uint32_t> queue{seed};
      group_of_[seed] = group;
      while (!queue.empty()) {
        const std::uint32_t root = queue.front();
        queue.pop_front();
        for (std::uint32_t i = first[root]; i < end_of[root]; ++i) {
          const std::uint32_t b = touching[i];
          if (behaviour_done[b]) continue;
          behaviour_done[b] = 1;
          // The behaviour's start as this class places it, through one of its points here.
          double start = 0;
          bool found = false;
          for_each_placing_point(b, [&](std::uint32_t p) {
            const std::uint32_t v = vars_.base[b] + p;
            if (!found && classes_.find(v) == root) {
              start = class_time_[root] + classes_.offset(v) - default_offset(behaviours_[b], p);
              found = true;
            }
          });
          for_each_placing_point(b, [&](std::uint32_t p) {
            const std::uint32_t v = vars_.base[b] + p;
            const std::uint32_t other = classes_.find(v);
            if (group_of_[other] != kNone) return;
            group_of_[other] = group;
            class_time_[other] = start + default_offset(behaviours_[b], p) - classes_.offset(v);
            queue.push_back(other);
          });
        }
      }
    };
    group_shift_.push_back(0);
    group_free_.push_back(0);
    const std::uint32_t zero_root = classes_.find(vars_.zero);
    class_time_[zero_root] = -classes_.offset(vars_.zero);  // the block's start is at 0
    spread(zero_root, 0);
    for (std::uint32_t b = 0; b < behaviours_.size(); ++b) {
      const std::uint32_t root = classes_.find(vars_.base[b]);
      if (group_of_[root] != kNone) continue;
      const auto group = static_cast<std::uint32_t>(group_shift_.size());
      group_shift_.push_back(0);
      group_free_.push_back(1);
      class_time_[root] = 0;
      spread(root, group);
    }
    // A free group starts with its earliest behaviour at the block's start.
    std::vector<double> earliest(group_shift_.size(), std::numeric_limits<double>::infinity());
    for (std::uint32_t b = 0; b < behaviours_.size(); ++b) {
      const std::uint32_t g = group_of_[classes_.find(vars_.base[b])];
      if (group_free_[g]) earliest[g] = std::min(earliest[g], start_of(b));
    }
    for (std::size_t g = 1; g < group_shift_.size(); ++g)
      if (std::isfinite(earliest[g])) group_shift_[g] = -earliest[g];
  }

  // The start as the behaviour's placing points put it: the earliest they imply.
  double start_of(std::uint32_t b) {
    double start = std::numeric_limits<double>::infinity();
    for_each_placing_point(b, [&](std::uint32_t p) {
      start = std::min(start, time_of(vars_.base[b] + p) - default_offset(behaviours_[b], p));
    });
    return start;
  }

  std::optional<SolveError> apply_inequalities() {
    for (int pass = 0; pass < 2; ++pass) {
      for (const Relation& r : relations_) {
        if (r.kind != Relation::Kind::at_least) continue;
        const std::uint32_t a = vars_.of(r.a);
        const double want = (r.b ? time_of(vars_.of(*r.b)) : 0.0) + r.offset;
        const double have = time_of(a);
        if (have + kTolerance >= want) continue;
        const std::uint32_t group = group_of_[classes_.find(a)];
        const std::uint32_t b_group = r.b ? group_of_[classes_.find(vars_.of(*r.b))] : 0;
        if (pass == 0 && b_group != group) {
          // The free side moves: the later one later, else the earlier one earlier.
          if (group_free_[group]) {
            group_shift_[group] += want - have;
            continue;
          }
          if (group_free_[b_group]) {
            group_shift_[b_group] -= want - have;
            continue;
          }
        }
        SolveError e;
        e.what = SolveError::What::unmet;
        e.label = r.label;
        e.time = want;
        e.other_time = have;
        if (first_label_[a] >= 0 && first_label_[a] != r.label) e.chain.push_back(first_label_[a]);
        return e;
      }
    }
    return std::nullopt;
  }

  std::optional<SolveError> fill(Solution& out) {
    out.points.resize(behaviours_.size());
    out.marks.resize(behaviours_.size());
    for (std::uint32_t b = 0; b < behaviours_.size(); ++b) {
      const SolverBehaviour& beh = behaviours_[b];
      const std::uint32_t base = vars_.base[b];
      auto& t = out.points[b];
      // Named standard points keep their times; the others go between them by their defaults.
      std::array<bool, kStandardPoints> known{};
      for (std::uint32_t p = 0; p < kStandardPoints; ++p) {
        known[p] = p == kStart ? named_[base] != 0 : named_[base + p] != 0 || beh.rigid;
        if (known[p]) t[p] = time_of(base + p);
      }
      if (!known[kStart]) {
        // A start no constraint names is never before the block: the preparation is shortened.
        known[kStart] = true;
        double first_named = std::numeric_limits<double>::infinity();
        for (std::uint32_t p = 1; p < kStandardPoints; ++p)
          if (known[p]) first_named = std::min(first_named, t[p]);
        t[kStart] = start_of(b);
        if (!beh.rigid && t[kStart] < 0) t[kStart] = std::min(0.0, first_named);
      }
      std::uint32_t last = kStart;
      for (std::uint32_t p = 1; p < kStandardPoints; ++p) {
        if (!known[p]) continue;
        if (t[p] + kTolerance < t[last]) return order_error(b, p, last, t[p], t[last]);
        for (std::uint32_t q = last + 1; q < p; ++q) {
          const double span = beh.defaults[p] - beh.defaults[last];
          const double f = span > 0 ? (beh.defaults[q] - beh.defaults[last]) / span : 0.0;
          t[q] = t[last] + f * (t[p] - t[last]);
        }
        last = p;
      }
      for (std::uint32_t q = last + 1; q < kStandardPoints; ++q) t[q] = t[last] + beh.defaults[q] - beh.defaults[last];
      for (std::uint32_t m = 0; m < beh.marks.size(); ++m) out.marks[b].push_back(time_of(base + kStandardPoints + m));
      if (t[kStart] < -kTolerance) {
        SolveError e;
        e.what = SolveError::What::before_block;
        e.behaviour = b;
        e.time = t[kStart];
        e.label = first_label_of(b);
        if (beh.rigid && beh.own_label >= 0) e.chain.push_back(beh.own_label);
        return e;
      }
    }
    return std::nullopt;
  }

  int first_label_of(std::uint32_t b) {
    const SolverBehaviour& beh = behaviours_[b];
    const std::uint32_t points = kStandardPoints + static_cast<std::uint32_t>(beh.marks.size());
    for (std::uint32_t p = 0; p < points; ++p)
      if (first_label_[vars_.base[b] + p] >= 0) return first_label_[vars_.base[b] + p];
    return beh.own_label;
  }

  SolveError order_error(std::uint32_t b, std::uint32_t p, std::uint32_t before, double tp, double tb) {
    SolveError e;
    e.what = SolveError::What::order;
    e.behaviour = b;
    e.point = p;
    e.other = before;
    e.time = tp;
    e.other_time = tb;
    const std::uint32_t base = vars_.base[b];
    // Named at the later of the two constraints (in document order): the one that cannot hold.
    const int lp = first_label_[base + p];
    const int lb = first_label_[base + before];
    e.label = std::max(lp, lb);
    const int other = std::min(lp, lb);
    if (other >= 0 && other != e.label) e.chain.push_back(other);
    return e;
  }
};

}  // namespace

Solved solve(const std::vector<SolverBehaviour>& behaviours, const std::vector<Relation>& relations) {
  return Solver(behaviours, relations).run();
}

}  // namespace fapc::bml
