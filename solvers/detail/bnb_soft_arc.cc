#include "sightline/solvers/detail/bnb_soft_arc.h"

#include <algorithm>
#include <cmath>

namespace sightline::solvers::detail {

namespace {
// Steps (queue items processed) one propagate() may take before it stops early; far above
// what the instances need, it only guards against a propagation that would not settle.
constexpr std::uint64_t kMaxSteps = 1'000'000;
}  // namespace

void SoftArcConsistency::load(const WcspView& view, Level level) {
  view_ = &view;
  level_ = level;
  top_ = kForbidden;
  checked_top_ = kForbidden + 1;  // the first propagate() checks every value
  c0_ = 0;
  const std::size_t n = view.num_variables();
  unary_ = view.unary;
  alive_.assign(view.offset[n], 1);
  size_.resize(n);
  for (std::size_t v = 0; v < n; ++v) size_[v] = view.size(static_cast<csp::VariableId>(v));
  const std::size_t m = view.edges.size();
  delta_x_.resize(m);
  delta_y_.resize(m);
  std::size_t total = 0;
  neighbours_.assign(n, {});
  for (std::uint32_t e = 0; e < m; ++e) {
    const WcspView::Edge& edge = view.edges[e];
    delta_x_[e] = static_cast<std::uint32_t>(total);
    total += view.size(edge.x);
    delta_y_[e] = static_cast<std::uint32_t>(total);
    total += view.size(edge.y);
    neighbours_[edge.x].push_back({e, edge.y, true});
    neighbours_[edge.y].push_back({e, edge.x, false});
  }
  deltas_.assign(total, 0);
  const std::size_t k = view.nary.size();
  nary_of_.assign(n, {});
  for (std::uint32_t i = 0; i < k; ++i) {
    for (csp::VariableId v : view.problem->constraint(view.nary[i]).scope())
      nary_of_[v].push_back(i);
  }
  nary_done_.assign(k, 0);
  in_nary_.assign(k, 0);
  nary_queue_.clear();
  values_.assign(n, 0.0);
  assigned_.assign(n, 0);
  support_.assign(total, 0);
  full_support_.assign(total, 0);
  trail_.clear();
  in_ac_.assign(2 * m, 0);
  in_dac_.assign(m, 0);
  in_eac_.assign(n, 0);
  in_nc_.assign(n, 0);
  ac_queue_.clear();
  dac_queue_.clear();
  eac_queue_.clear();
  nc_queue_.clear();
  failed_ = false;
  prune_all_ = false;
  stopped_ = false;
  last_edge_ = -1;
  // The first propagate() enforces the level everywhere.
  for (std::uint32_t e = 0; e < m; ++e) {
    push_ac(e, true);
    push_ac(e, false);
    if (level_ >= Level::kDirectional) push_dac(e);
  }
  for (std::uint32_t i = 0; i < k; ++i) {
    in_nary_[i] = 1;
    nary_queue_.push_back(i);
  }
  for (csp::VariableId v = 0; v < n; ++v) {
    push_nc(v);
    if (level_ == Level::kExistential) push_eac(v);
  }
}

std::int64_t SoftArcConsistency::binary(std::size_t e, std::uint32_t a, std::uint32_t b) const {
  return cost(static_cast<std::uint32_t>(e), a, b);
}

void SoftArcConsistency::push_ac(std::uint32_t e, bool onto_x) {
  const std::uint32_t item = 2 * e + (onto_x ? 0 : 1);
  if (in_ac_[item]) return;
  in_ac_[item] = 1;
  ac_queue_.push_back(item);
}
// The DAC queue is a binary heap on the edge's y (highest first), so a pop costs
// O(log queue) instead of a scan of the queue: at the root every edge is queued, and
// scanning thousands of edges per pop was most of the time on large instances.
bool SoftArcConsistency::dac_before(std::uint32_t e, std::uint32_t f) const {
  return view_->edges[e].y < view_->edges[f].y;
}
void SoftArcConsistency::push_dac(std::uint32_t e) {
  if (in_dac_[e]) return;
  in_dac_[e] = 1;
  dac_queue_.push_back(e);
  std::push_heap(dac_queue_.begin(), dac_queue_.end(),
                 [this](std::uint32_t a, std::uint32_t b) { return dac_before(a, b); });
}
void SoftArcConsistency::push_eac(csp::VariableId v) {
  if (in_eac_[v]) return;
  in_eac_[v] = 1;
  eac_queue_.push_back(v);
}
void SoftArcConsistency::push_nc(csp::VariableId v) {
  if (in_nc_[v]) return;
  in_nc_[v] = 1;
  nc_queue_.push_back(v);
}

void SoftArcConsistency::clear_queues() {
  for (std::uint32_t e : ac_queue_) in_ac_[e] = 0;
  for (std::uint32_t e : dac_queue_) in_dac_[e] = 0;
  for (csp::VariableId v : eac_queue_) in_eac_[v] = 0;
  for (csp::VariableId v : nc_queue_) in_nc_[v] = 0;
  for (std::uint32_t i : nary_queue_) in_nary_[i] = 0;
  ac_queue_.clear();
  dac_queue_.clear();
  eac_queue_.clear();
  nc_queue_.clear();
  nary_queue_.clear();
}

// C_v went up: its own unary support and pruning, full supports of lower neighbours in v,
// existential supports of v and its neighbours.
void SoftArcConsistency::unary_increased(csp::VariableId v) {
  push_nc(v);
  if (level_ < Level::kDirectional) return;
  for (const Neighbour& nb : neighbours_[v]) {
    if (!nb.is_x) push_dac(nb.edge);
    if (level_ == Level::kExistential) push_eac(nb.other);
  }
  if (level_ == Level::kExistential) push_eac(v);
}

// Costs of edge e went up in some columns (an extension from the side opposite `onto_x`,
// then projected onto `onto_x`'s rows): that side's simple supports, and full supports.
void SoftArcConsistency::edge_changed(std::uint32_t e, bool onto_x) {
  if (level_ < Level::kArc) return;
  push_ac(e, !onto_x);
  if (level_ < Level::kDirectional) return;
  push_dac(e);
  if (level_ == Level::kExistential) {
    push_eac(view_->edges[e].x);
    push_eac(view_->edges[e].y);
  }
}

void SoftArcConsistency::value_removed(csp::VariableId v) {
  push_nc(v);
  for (const Neighbour& nb : neighbours_[v]) {
    push_ac(nb.edge, !nb.is_x);  // the other side's supports in v (kNode: once v is fixed)
    if (level_ >= Level::kDirectional && !nb.is_x) push_dac(nb.edge);
    if (level_ == Level::kExistential) push_eac(nb.other);
  }
  if (level_ == Level::kExistential) push_eac(v);
}

bool SoftArcConsistency::remove(csp::VariableId v, std::uint32_t a) {
  std::int64_t& flag = alive_[view_->offset[v] + a];
  if (!flag) return !failed_;
  set(flag, 0);
  set(size_[v], size_[v] - 1);
  if (size_[v] == 0) {
    failed_ = true;
    return false;
  }
  value_removed(v);
  if (size_[v] == 1) {
    for (std::uint32_t i : nary_of_[v]) {
      if (!in_nary_[i] && !nary_done_[i]) {
        in_nary_[i] = 1;
        nary_queue_.push_back(i);
      }
    }
  }
  return !failed_;
}

bool SoftArcConsistency::assign(csp::VariableId v, std::uint32_t a) {
  if (!alive(v, a)) {
    failed_ = true;
    return false;
  }
  for (std::uint32_t b = 0; b < view_->size(v) && !failed_; ++b) {
    if (b != a) remove(v, b);
  }
  return !failed_;
}

bool SoftArcConsistency::prune(csp::VariableId v) {
  const std::uint32_t begin = view_->offset[v], size = view_->size(v);
  const std::int64_t* alive = alive_.data() + begin;
  const std::int64_t* unary = unary_.data() + begin;
  // c0 + C(a) >= top, without overflow: C(a) >= top - c0 (c0 < top here).
  const std::int64_t room = top_ - c0_;
  for (std::uint32_t a = 0; a < size && !failed_; ++a) {
    if (alive[a] && unary[a] >= room) remove(v, a);
  }
  return !failed_;
}

// NC*: the least unary cost of v moves into c0 (so some value costs 0), then values that
// reach top with c0 are removed. A raised c0 can prune any variable: the caller rescans.
bool SoftArcConsistency::node_consistency(csp::VariableId v) {
  const std::uint32_t begin = view_->offset[v];
  std::int64_t least = kForbidden;
  for (std::uint32_t a = 0; a < view_->size(v); ++a) {
    if (alive_[begin + a]) least = std::min(least, unary_[begin + a]);
  }
  if (least >= kForbidden) {
    failed_ = true;
    return false;
  }
  if (least > 0) {
    for (std::uint32_t a = 0; a < view_->size(v); ++a) {
      std::int64_t& u = unary_[begin + a];
      if (alive_[begin + a] && u < kForbidden) set(u, u - least);
    }
    set(c0_, add_cost(c0_, least));
    if (c0_ >= top_) {
      failed_ = true;
      return false;
    }
    // Every variable may now have values that reach top with c0: they are pruned once the
    // queues are empty (propagate), not here, where a propagation raising c0 many times
    // would scan every domain each time. Keeping them a while longer is sound (pruning only
    // strengthens) and the state is fully pruned when propagate() returns.
    prune_all_ = true;
  }
  return prune(v);
}

void SoftArcConsistency::list_alive(csp::VariableId v, std::vector<std::uint32_t>& out) const {
  out.clear();
  const std::int64_t* alive = alive_.data() + view_->offset[v];
  const std::uint32_t size = view_->size(v);
  for (std::uint32_t b = 0; b < size && out.size() < static_cast<std::size_t>(size_[v]); ++b) {
    if (alive[b]) out.push_back(b);
  }
}

bool SoftArcConsistency::project_simple(std::uint32_t e, bool onto_x) {
  const WcspView::Edge& edge = view_->edges[e];
  const csp::VariableId s = onto_x ? edge.x : edge.y, o = onto_x ? edge.y : edge.x;
  const std::uint32_t ds = view_->size(s);
  const std::uint32_t sb = view_->offset[s], ob = view_->offset[o];
  bool moved = false;
  std::uint32_t* support = support_.data() + (onto_x ? delta_x_[e] : delta_y_[e]);
  const SidedPair pair = sided(e, onto_x);
  const std::int64_t* alive_s = alive_.data() + sb;
  const std::int64_t* alive_o = alive_.data() + ob;
  // The alive values of the other side, listed once (when a row first needs a scan), so a
  // row scan costs the alive count, not the domain size: deep in the search most domains
  // are down to a few values (one, once assigned) out of tens.
  std::vector<std::uint32_t>& alive_list = scratch_alive_;
  alive_list.clear();
  bool listed = false;
  for (std::uint32_t a = 0; a < ds; ++a) {
    if (!alive_s[a]) continue;
    const std::uint32_t hint = support[a];
    if (alive_o[hint] && pair.at(a, hint) == 0) continue;
    if (!listed) {
      list_alive(o, alive_list);
      listed = true;
    }
    std::int64_t least = kForbidden;
    for (const std::uint32_t b : alive_list) {
      const std::int64_t c = pair.at(a, b);
      if (c < least) {
        least = c;
        support[a] = b;
        if (c == 0) break;
      }
    }
    if (least == 0) continue;
    moved = true;
    std::int64_t& u = unary_[sb + a];
    if (least >= kForbidden) {
      set(u, kForbidden);  // no allowed pair left: the value goes at the next pruning
    } else {
      std::int64_t& d = delta(e, onto_x, a);
      set(d, d + least);
      set(u, add_cost(u, least));
    }
  }
  if (moved) {
    last_edge_ = e;
    unary_increased(s);
  }
  return moved;
}

bool SoftArcConsistency::project_full(std::uint32_t e, bool onto_x) {
  const WcspView::Edge& edge = view_->edges[e];
  const csp::VariableId s = onto_x ? edge.x : edge.y, o = onto_x ? edge.y : edge.x;
  const std::uint32_t ds = view_->size(s);
  const std::uint32_t sb = view_->offset[s], ob = view_->offset[o];
  const SidedPair pair = sided(e, onto_x);
  auto pair_cost = [&pair](std::uint32_t a, std::uint32_t b) { return pair.at(a, b); };
  // alpha[a]: the least C(a, b) + C_o(b): what a full support of a lacks.
  scratch_alpha_.assign(ds, 0);
  bool lacking = false;
  std::uint32_t* support = full_support_.data() + (onto_x ? delta_x_[e] : delta_y_[e]);
  std::vector<std::uint32_t>& alive_list = scratch_alive_;
  list_alive(o, alive_list);  // as in project_simple
  for (std::uint32_t a = 0; a < ds; ++a) {
    if (!alive_[sb + a]) continue;
    const std::uint32_t hint = support[a];
    if (alive_[ob + hint] && pair_cost(a, hint) == 0 && unary_[ob + hint] == 0) continue;
    std::int64_t least = kForbidden;
    for (const std::uint32_t b : alive_list) {
      const std::int64_t c = add_cost(pair_cost(a, b), unary_[ob + b]);
      if (c < least) {
        least = c;
        support[a] = b;
        if (c == 0) break;
      }
    }
    scratch_alpha_[a] = least;
    lacking = lacking || least > 0;
  }
  if (!lacking) return false;
  // Extension: P(b) = max over a of alpha[a] - C(a, b) (at most C_o(b), since alpha[a] <=
  // C(a, b) + C_o(b)) moves from C_o(b) into column b, so every row a can then give alpha[a].
  for (const std::uint32_t b : alive_list) {
    std::int64_t need = 0;
    for (std::uint32_t a = 0; a < ds; ++a) {
      if (!alive_[sb + a] || scratch_alpha_[a] == 0 || scratch_alpha_[a] >= kForbidden) continue;
      const std::int64_t c = pair_cost(a, b);
      if (c < kForbidden) need = std::max(need, scratch_alpha_[a] - c);
    }
    if (need > 0) {
      std::int64_t& d = delta(e, !onto_x, b);
      set(d, d - need);
      set(unary_[ob + b], unary_[ob + b] - need);
    }
  }
  for (std::uint32_t a = 0; a < ds; ++a) {
    const std::int64_t alpha = scratch_alpha_[a];
    if (!alive_[sb + a] || alpha == 0) continue;
    std::int64_t& u = unary_[sb + a];
    if (alpha >= kForbidden) {
      set(u, kForbidden);
    } else {
      std::int64_t& d = delta(e, onto_x, a);
      set(d, d + alpha);
      set(u, add_cost(u, alpha));
    }
  }
  last_edge_ = e;
  unary_increased(s);
  edge_changed(e, onto_x);
  return true;
}

void SoftArcConsistency::revise_side(std::uint32_t item) {
  const std::uint32_t e = item / 2;
  const bool onto_x = item % 2 == 0;
  const WcspView::Edge& edge = view_->edges[e];
  // NC* projects a pair only once the other side is fixed (forward checking).
  if (level_ == Level::kNode && size_[onto_x ? edge.y : edge.x] != 1) return;
  project_simple(e, onto_x);
}

// EAC on v: the least, over alive a, of C_v(a) + sum over pairs of what a's full support
// lacks; when positive, full supports toward v on every pair make C_v(a) >= it everywhere,
// and NC* moves it into c0.
void SoftArcConsistency::revise_existential(csp::VariableId v) {
  const std::uint32_t vb = view_->offset[v], dv = view_->size(v);
  std::int64_t best = kForbidden;
  for (std::uint32_t a = 0; a < dv && best > 0; ++a) {
    if (!alive_[vb + a]) continue;
    std::int64_t sum = unary_[vb + a];
    for (const Neighbour& nb : neighbours_[v]) {
      if (sum >= best) break;
      const std::uint32_t ob = view_->offset[nb.other];
      const SidedPair pair = sided(nb.edge, nb.is_x);
      auto lack = [&](std::uint32_t b) { return add_cost(pair.at(a, b), unary_[ob + b]); };
      std::uint32_t& hint = full_support_[(nb.is_x ? delta_x_[nb.edge] : delta_y_[nb.edge]) + a];
      if (alive_[ob + hint] && lack(hint) == 0) continue;
      std::int64_t least = kForbidden;
      for (std::uint32_t b = 0; b < view_->size(nb.other) && least > 0; ++b) {
        if (!alive_[ob + b]) continue;
        const std::int64_t c = lack(b);
        if (c < least) {
          least = c;
          hint = b;
        }
      }
      sum = add_cost(sum, least);
    }
    best = std::min(best, sum);
  }
  if (best == 0) return;
  for (const Neighbour& nb : neighbours_[v]) project_full(nb.edge, nb.is_x);
  push_nc(v);
}

std::int64_t SoftArcConsistency::support_cost(csp::VariableId v, std::uint32_t a) const {
  std::int64_t sum = unary_[view_->offset[v] + a];
  for (const Neighbour& nb : neighbours_[v]) {
    const std::uint32_t ob = view_->offset[nb.other];
    const SidedPair pair = sided(nb.edge, nb.is_x);
    std::int64_t least = kForbidden;
    for (std::uint32_t b = 0; b < view_->size(nb.other) && least > 0; ++b) {
      if (alive_[ob + b]) least = std::min(least, add_cost(pair.at(a, b), unary_[ob + b]));
    }
    sum = add_cost(sum, least);
  }
  return sum;
}

bool SoftArcConsistency::propagate() {
  if (failed_ || c0_ >= top_) {
    clear_queues();
    failed_ = false;
    return false;
  }
  // top may have dropped since this state's values were last checked against it (the top
  // they were checked with is trailed, so an undone state brings its own back).
  if (checked_top_ > top_) {
    set(checked_top_, top_);
    for (csp::VariableId v = 0; v < size_.size() && !failed_; ++v) prune(v);
  }
  std::uint64_t steps = 0;
  while (!failed_ && ++steps <= kMaxSteps) {
    if (steps % kStopStride == 0 && stop_ && stop_()) {
      stopped_ = failed_ = true;
      break;
    }
    if (!nc_queue_.empty()) {
      const csp::VariableId v = nc_queue_.back();
      nc_queue_.pop_back();
      in_nc_[v] = 0;
      node_consistency(v);
    } else if (!nary_queue_.empty()) {
      const std::uint32_t i = nary_queue_.back();
      nary_queue_.pop_back();
      in_nary_[i] = 0;
      revise_nary(i);
    } else if (!ac_queue_.empty()) {
      const std::uint32_t item = ac_queue_.back();
      ac_queue_.pop_back();
      in_ac_[item] = 0;
      revise_side(item);
    } else if (!dac_queue_.empty()) {
      // Highest y first: costs then flow down toward lower ids in one sweep.
      std::pop_heap(dac_queue_.begin(), dac_queue_.end(),
                    [this](std::uint32_t a, std::uint32_t b) { return dac_before(a, b); });
      const std::uint32_t e = dac_queue_.back();
      dac_queue_.pop_back();
      in_dac_[e] = 0;
      project_full(e, true);  // x < y: costs flow toward the lower id
    } else if (!eac_queue_.empty()) {
      const csp::VariableId v = eac_queue_.back();
      eac_queue_.pop_back();
      in_eac_[v] = 0;
      revise_existential(v);
    } else if (prune_all_) {
      prune_all_ = false;
      for (csp::VariableId v = 0; v < size_.size() && !failed_; ++v) prune(v);
    } else {
      break;
    }
  }
  prune_all_ = false;
  const bool ok = !failed_ && c0_ < top_ && add_cost(c0_, open_nary_bound()) < top_;
  clear_queues();
  failed_ = false;
  return ok;
}

void SoftArcConsistency::undo(std::size_t mark) {
  while (trail_.size() > mark) {
    *trail_.back().cell = trail_.back().old;
    trail_.pop_back();
  }
}

std::vector<std::int64_t> SoftArcConsistency::snapshot() const {
  std::vector<std::int64_t> s{c0_};
  s.insert(s.end(), unary_.begin(), unary_.end());
  s.insert(s.end(), alive_.begin(), alive_.end());
  s.insert(s.end(), size_.begin(), size_.end());
  s.insert(s.end(), deltas_.begin(), deltas_.end());
  s.insert(s.end(), nary_done_.begin(), nary_done_.end());
  s.push_back(checked_top_);
  return s;
}

}  // namespace sightline::solvers::detail
