#include "workspace/journal.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <set>
#include <stdexcept>

#include "workspace/kernels/data_error.h"
#include "workspace/kernels/surface.h"
#include "workspace/variables.h"

namespace igds {

namespace {

// Bit for bit: -0.0 and NaNs are values of their own, as the session keeps them.
bool same_bits(const double* a, const double* b, std::size_t n) {
  return n == 0 || std::memcmp(a, b, n * sizeof(double)) == 0;
}

// Runs of differing elements closer than this are kept as one range (fewer ranges to store).
constexpr std::size_t range_gap = 8;

// What changed from `from` to `to`, without its values (take_values); `edits` (the Edits since
// the last save) covers every change.
ArrayChange change_of(const Array& from, const Array& to, const Edits& edits) {
  ArrayChange c;
  c.shape_before = from.shape;
  c.shape_after = to.shape;
  const std::size_t n = to.size();
  if (from.shape == to.shape && !edits.whole) {
    auto ranges = edits.ranges;
    for (auto& [first, end] : ranges) end = std::min(end, n);
    std::erase_if(ranges, [](const auto& r) { return r.first >= r.second; });
    std::sort(ranges.begin(), ranges.end());
    for (const auto& [first, end] : ranges) {
      if (!c.ranges.empty() && first <= c.ranges.back().second)
        c.ranges.back().second = std::max(c.ranges.back().second, end);
      else
        c.ranges.emplace_back(first, end);
    }
  } else if (from.shape == to.shape) {
    // Replaced whole with the same shape (RESTORE, UNDO): the parts that differ, when few.
    std::size_t k = 0, changed = 0;
    while (k < n) {
      if (same_bits(from.data() + k, to.data() + k, 1)) {
        ++k;
        continue;
      }
      std::size_t end = k + 1;
      for (std::size_t j = end, gap = 0; j < n && gap < range_gap; ++j) {
        if (same_bits(from.data() + j, to.data() + j, 1)) {
          ++gap;
        } else {
          end = j + 1;
          gap = 0;
        }
      }
      c.ranges.emplace_back(k, end);
      changed += end - k;
      k = end;
    }
    if (changed * 2 > n) {
      c.ranges.clear();
      c.whole = true;
    }
  } else {
    c.whole = true;
  }
  return c;
}

// The bytes of the values take_values gives change_of's `c` (ArrayChange::bytes() counts them
// once they are there).
std::size_t value_bytes(const ArrayChange& c, const Array& from, const Array& to) {
  std::size_t values = c.whole ? from.size() + to.size() : 0;
  for (const auto& [first, end] : c.ranges) values += 2 * (end - first);
  return values * sizeof(double);
}

// The values of change_of's `c`, from the two arrays it was found between.
void take_values(ArrayChange& c, const Array& from, const Array& to) {
  if (c.whole) {
    assign_large(c.before, from.ravel);
    assign_large(c.after, to.ravel);
    return;
  }
  for (const auto& [first, end] : c.ranges) {
    c.before.insert(c.before.end(), from.ravel.begin() + first, from.ravel.begin() + end);
    c.after.insert(c.after.end(), to.ravel.begin() + first, to.ravel.begin() + end);
  }
}

// `a` made from `from` (its shape, the values where the change applies) to `to`.
bool apply_change(const ArrayChange& c, Array& a, bool back) {
  const auto& from_shape = back ? c.shape_after : c.shape_before;
  const auto& to_shape = back ? c.shape_before : c.shape_after;
  const auto& from = back ? c.after : c.before;
  const auto& to = back ? c.before : c.after;
  if (a.shape != from_shape) return false;
  if (c.whole) {
    if (a.size() != from.size() || Array::count(to_shape) != to.size() ||
        !same_bits(a.data(), from.data(), from.size()))
      return false;
    a.shape = to_shape;
    assign_large(a.ravel, to);
    return true;
  }
  if (from_shape != to_shape || from.size() != to.size()) return false;
  std::size_t at = 0, previous_end = 0;
  for (const auto& [first, end] : c.ranges) {
    if (first < previous_end || first >= end || end > a.size() || end - first > from.size() - at)
      return false;
    if (!same_bits(a.data() + first, from.data() + at, end - first)) return false;
    previous_end = end;
    at += end - first;
  }
  if (at != from.size()) return false;
  at = 0;
  for (const auto& [first, end] : c.ranges) {
    std::copy(to.begin() + static_cast<std::ptrdiff_t>(at),
              to.begin() + static_cast<std::ptrdiff_t>(at + end - first), a.ravel.begin() + first);
    at += end - first;
  }
  return true;
}

void mark_edits(const ArrayChange& c, Edits& edits) {
  if (c.whole) return edits.all();
  for (const auto& [first, end] : c.ranges) edits.part(first, end);
}

}  // namespace

Settings Settings::of(const Workspace& ws) {
  return {ws.nocur, ws.nostr, ws.intcu, ws.intst, ws.status};
}

void Settings::apply_to(Workspace& ws) const {
  ws.nocur = nocur;
  ws.nostr = nostr;
  ws.intcu = intcu;
  ws.intst = intst;
  ws.status = status;
}

std::size_t ArrayChange::bytes() const {
  return (before.size() + after.size()) * sizeof(double) +
         ranges.size() * 2 * sizeof(std::uint64_t);
}

bool ArrayChange::forward(Array& a) const {
  return apply_change(*this, a, false);
}

bool ArrayChange::backward(Array& a) const {
  return apply_change(*this, a, true);
}

ImageSlots images_of(const Workspace& ws) {
  return {ws.image, ws.temp1, ws.temp2};
}

std::size_t JournalStep::bytes() const {
  return name.size() + 2 * sizeof(Settings) + inppn.bytes() + inptg.bytes();
}

Journal::Journal(const Workspace& ws)
    : current_{Settings::of(ws), ws.inppn, ws.inptg, ws.changes.surface}, images_(images_of(ws)) {}

bool Journal::record(const Workspace& ws, std::string_view name) {
  const Settings settings = Settings::of(ws);
  const ImageSlots images = images_of(ws);
  const bool surface = ws.changes.surface != current_.generation;
  if (!surface && settings == current_.settings && images == images_) return false;
  JournalStep step;
  step.name = std::string(name);
  step.before = current_.settings;
  step.after = settings;
  // A step larger than the bound alone cannot be undone (bound() would drop it, and every step
  // before it): its values are never copied, and the journal starts again from `ws`.
  bool kept = true;
  if (surface) {
    step.inppn = change_of(current_.inppn, ws.inppn, ws.changes.inppn);
    step.inptg = change_of(current_.inptg, ws.inptg, ws.changes.inptg);
    kept = step.bytes() + value_bytes(step.inppn, current_.inppn, ws.inppn) +
               value_bytes(step.inptg, current_.inptg, ws.inptg) <=
           max_bytes;
    if (kept) {
      take_values(step.inppn, current_.inppn, ws.inppn);
      take_values(step.inptg, current_.inptg, ws.inptg);
    }
  } else {
    step.inppn.shape_before = step.inppn.shape_after = current_.inppn.shape;
    step.inptg.shape_before = step.inptg.shape_after = current_.inptg.shape;
  }
  step.images_before = images_;
  step.images_after = images;
  step.generation_before = current_.generation;
  step.generation_after = ws.changes.surface;

  // The current state follows `ws`, copying only what changed (all of it, into the memory it
  // has, after a step not kept).
  if (!kept) {
    current_.inppn = ws.inppn;
    current_.inptg = ws.inptg;
  } else {
    for (auto [c, mine] :
         {std::pair{&step.inppn, &current_.inppn}, {&step.inptg, &current_.inptg}}) {
      if (!c->forward(*mine)) {
        // Never expected (the Edits cover every change): the journal starts again from `ws`.
        *this = Journal(ws);
        return false;
      }
    }
  }
  current_.settings = settings;
  current_.generation = ws.changes.surface;
  images_ = images;
  if (!kept) {
    steps_.clear();
    position_ = 0;
    bytes_ = 0;
    return true;
  }
  // A surface made again equal to itself (RESTORE of the same file) is no step.
  if (step.inppn.unchanged() && step.inptg.unchanged() && step.before == step.after &&
      step.images_before == step.images_after)
    return false;

  steps_.resize(position_);
  bytes_ = 0;
  for (const JournalStep& s : steps_) bytes_ += s.bytes();
  bytes_ += step.bytes();
  steps_.push_back(std::move(step));
  ++position_;
  bound();
  return true;
}

std::size_t Journal::held_image_bytes() const {
  std::set<const void*> seen;
  for (const ImageRef& image : images_) seen.insert(image.watch().lock().get());
  std::size_t bytes = 0;
  for (const JournalStep& s : steps_) {
    for (const auto* images : {&s.images_before, &s.images_after}) {
      for (const ImageRef& image : *images) {
        // An image not made yet (a recipe read from the disk) holds nothing.
        if (!image || !image.made() || !seen.insert(image.watch().lock().get()).second) continue;
        bytes += image->bytes();
      }
    }
  }
  return bytes;
}

void Journal::bound() {
  while (!steps_.empty() && (steps_.size() > max_steps || bytes_ > max_bytes ||
                             held_image_bytes() > max_image_bytes)) {
    if (position_ > 0) {
      bytes_ -= steps_.front().bytes();
      steps_.erase(steps_.begin());
      --position_;
    } else {
      bytes_ -= steps_.back().bytes();
      steps_.pop_back();
    }
  }
}

void Journal::apply(Workspace& ws, const JournalStep& step, bool back) {
  const Settings& to = back ? step.before : step.after;
  // The inputs of that state: an array the step changed is copied and changed (the current one
  // stays until the surface is made), one it left is read where it is.
  const bool new_inppn = !step.inppn.unchanged(), new_inptg = !step.inptg.unchanged();
  Array inppn = new_inppn ? current_.inppn : Array{}, inptg = new_inptg ? current_.inptg : Array{};
  if (!apply_change(step.inppn, new_inppn ? inppn : current_.inppn, back) ||
      !apply_change(step.inptg, new_inptg ? inptg : current_.inptg, back))
    throw std::logic_error("undo journal out of step with the workspace");
  const Array& to_inppn = new_inppn ? inppn : current_.inppn;
  const Array& to_inptg = new_inptg ? inptg : current_.inptg;
  const bool marks = to.status[Workspace::status_twists] == 1;
  // A step that left the surface as it was (a DISPLAY, a STORE) keeps PATCHES and INTPN: they are
  // the interpolation of the same inputs with the same twists already.
  const bool same_surface = step.generation_before == step.generation_after &&
                            ws.changes.surface == current_.generation && ws.changes.derived &&
                            ws.has_surface() && !new_inppn && !new_inptg && to.nocur == ws.nocur &&
                            to.nostr == ws.nostr && to.intcu == ws.intcu && to.intst == ws.intst &&
                            marks == ws.marks_twists();
  // Else INTPN is made again (the kernels are deterministic: bit for bit the same), with the
  // state's twists and PATCHES not kept (state.h), into the memory of the current one when it is
  // the interpolation of the current inputs (a 4 M-point surface then writes no fresh pages); on
  // DataError, or a result that is not finite (a state read from a forged file), PATCHES and
  // INTPN are as they were.
  const bool lend = ws.changes.derived && ws.has_surface();
  Surface surface;
  if (same_surface) {
    surface = {std::move(ws.patches), std::move(ws.intpn)};
  } else if (to.nocur > 0) {
    if (lend) surface.intpn = std::move(ws.intpn);
    try {
      if (auto overflow = interpolate_into(
              {to.nocur, to.nostr, to.intcu, to.intst, &to_inppn, &to_inptg, marks}, surface,
              PatchesOut::dropped)) {
        // The surface kept: finite when it was made.
        if (lend)
          (void)interpolate_into(
              {ws.nocur, ws.nostr, ws.intcu, ws.intst, &ws.inppn, &ws.inptg, ws.marks_twists()},
              surface, PatchesOut::dropped);
        throw *overflow;
      }
    } catch (...) {
      if (lend) ws.intpn = std::move(surface.intpn);
      throw;
    }
  }
  to.apply_to(ws);
  if (new_inppn) {
    current_.inppn = inppn;
    ws.inppn = std::move(inppn);
  }
  if (new_inptg) {
    current_.inptg = inptg;
    ws.inptg = std::move(inptg);
  }
  ws.patches = std::move(surface.patches);
  ws.intpn = std::move(surface.intpn);
  const ImageSlots& images = back ? step.images_before : step.images_after;
  ws.image = images[0];
  ws.temp1 = images[1];
  ws.temp2 = images[2];
  // The surface is again the one of that state: its images are recipes of it again.
  ws.changes.surface = back ? step.generation_before : step.generation_after;
  ws.changes.derived = true;
  if (!same_surface) keep_splines(ws, std::move(surface.tangents));
  mark_edits(step.inppn, ws.changes.inppn);
  mark_edits(step.inptg, ws.changes.inptg);
  current_.settings = to;
  current_.generation = ws.changes.surface;
  images_ = images;
}

std::optional<std::string> Journal::undo(Workspace& ws) {
  if (position_ == 0) return std::nullopt;
  apply(ws, steps_[position_ - 1], true);
  --position_;
  return steps_[position_].name;
}

std::optional<std::string> Journal::redo(Workspace& ws) {
  if (position_ == steps_.size()) return std::nullopt;
  apply(ws, steps_[position_], false);
  ++position_;
  return steps_[position_ - 1].name;
}

std::optional<std::string> Journal::rebuild(const Workspace& ws, std::vector<JournalStep> steps,
                                            std::size_t position) {
  if (position > steps.size() || steps.size() > max_steps) return "NUMBER OF STEPS";
  std::size_t bytes = 0;
  for (const JournalStep& s : steps) bytes += s.bytes();
  if (bytes > max_bytes) return "TOO LARGE";
  // Every state a generation of its own; the current one is the workspace's.
  std::vector<std::uint64_t> generations(steps.size() + 1);
  for (std::size_t k = 0; k < generations.size(); ++k)
    generations[k] = k == position ? ws.changes.surface : new_generation();

  // From the current state backwards, then forwards: each step must fit the state it starts
  // from, and each state must be a surface igds accepts.
  auto walk = [&](bool back) -> std::optional<std::string> {
    Workspace probe;
    Settings::of(ws).apply_to(probe);
    probe.inppn = ws.inppn;
    probe.inptg = ws.inptg;
    std::size_t state = position;
    while (back ? state > 0 : state < steps.size()) {
      const JournalStep& step = steps[back ? state - 1 : state];
      if (Settings::of(probe) != (back ? step.after : step.before)) return "STEPS DO NOT FOLLOW";
      if (!apply_change(step.inppn, probe.inppn, back) ||
          !apply_change(step.inptg, probe.inptg, back))
        return "STEPS DO NOT FOLLOW";
      (back ? step.before : step.after).apply_to(probe);
      state = back ? state - 1 : state + 1;
      if (auto p = status_problem(probe.status)) return "STATUS: " + p->reason;
      if (probe.nocur == 0) {
        // No surface yet (before the first BUILD): nothing else.
        if (probe.nostr != 0 || probe.intcu != 0 || probe.intst != 0 || !probe.inppn.empty() ||
            !probe.inptg.empty())
          return "STATE WITHOUT A SURFACE";
      } else if (step.inppn.whole || step.inptg.whole || !step.inptg.unchanged() ||
                 step.before.nocur != step.after.nocur || step.before.nostr != step.after.nostr ||
                 step.before.intcu != step.after.intcu || step.before.intst != step.after.intst) {
        if (auto p = size_problem(probe.nocur, probe.nostr, probe.intcu, probe.intst))
          return p->reason;
        if (auto p = surface_problem(probe)) return p->reason;
      } else {
        // Only ranges of INPPN changed, in a state that was checked whole: their values alone
        // (a start costs what the steps changed, not their number times INPPN).
        for (double v : back ? step.inppn.before : step.inppn.after)
          if (!std::isfinite(v)) return "INPPN HOLDS A NUMBER THAT IS NOT FINITE";
      }
    }
    return std::nullopt;
  };
  for (const JournalStep& s : steps)
    if (s.name.empty()) return "STEP NAME";
  if (auto p = walk(true)) return p;
  if (auto p = walk(false)) return p;
  for (std::size_t k = 0; k < steps.size(); ++k) {
    steps[k].generation_before = generations[k];
    steps[k].generation_after = generations[k + 1];
  }
  steps_ = std::move(steps);
  position_ = position;
  bytes_ = bytes;
  current_ = {Settings::of(ws), ws.inppn, ws.inptg, ws.changes.surface};
  images_ = images_of(ws);
  return std::nullopt;
}

void Journal::remember(const ImageRef& image, std::uint64_t generation, const Description& desim) {
  std::erase_if(remembered_, [](const Remembered& r) { return r.image.expired(); });
  remembered_.push_back({image.watch(), generation, desim});
}

std::optional<std::pair<std::uint64_t, Description>> Journal::recipe_of(
    const ImageRef& image) const {
  if (!image) return std::nullopt;
  for (const Remembered& r : remembered_)
    if (image.is(r.image)) return std::pair{r.generation, r.desim};
  return image.recipe();  // a deferred image is not made for it
}

JournalStates::JournalStates(const Journal& journal, const Workspace& ws)
    : settings_(Settings::of(ws)),
      inppn_(ws.inppn),
      inptg_(ws.inptg),
      generation_(ws.changes.surface),
      position_(journal.position()) {
  for (const JournalStep& s : journal.steps())
    steps_.push_back(
        {s.before, s.after, s.inppn, s.inptg, s.generation_before, s.generation_after});
}

const Settings& JournalStates::settings_of(std::size_t k) const {
  if (k == position_) return settings_;
  return k < steps_.size() ? steps_[k].before : steps_[k - 1].after;
}

std::uint64_t JournalStates::generation_of(std::size_t k) const {
  if (k == position_) return generation_;
  return k < steps_.size() ? steps_[k].generation_before : steps_[k - 1].generation_after;
}

Workspace JournalStates::inputs_of(std::size_t k) const {
  Workspace ws;
  settings_of(k).apply_to(ws);
  ws.inppn = inppn_;
  ws.inptg = inptg_;
  // Every step was found to fit the state it starts from when the journal was read.
  for (std::size_t state = position_; state > k; --state)
    if (!steps_[state - 1].inppn.backward(ws.inppn) || !steps_[state - 1].inptg.backward(ws.inptg))
      throw std::logic_error("undo journal out of step with its states");
  for (std::size_t state = position_; state < k; ++state)
    if (!steps_[state].inppn.forward(ws.inppn) || !steps_[state].inptg.forward(ws.inptg))
      throw std::logic_error("undo journal out of step with its states");
  ws.changes.surface = generation_of(k);
  return ws;
}

}  // namespace igds
