#include "workspace/disk/journal_file.h"

#include <map>
#include <memory>

#include "workspace/disk/frame.h"
#include "workspace/images.h"
#include "workspace/kernels/data_error.h"
#include "workspace/variables.h"

namespace igds::disk {

namespace {

constexpr std::uint32_t journal_version = 1;
constexpr std::size_t max_name_bytes = 40;

enum ImageKind : std::uint8_t { no_image = 0, slot_image = 1, recipe_image = 2, stored_image = 3 };

void write_settings(Writer& w, const Settings& s) {
  for (int v : {s.nocur, s.nostr, s.intcu, s.intst}) w.i32(v);
  for (int v : s.status) w.i32(v);
}

Settings read_settings(Reader& r) {
  Settings s;
  s.nocur = r.i32();
  s.nostr = r.i32();
  s.intcu = r.i32();
  s.intst = r.i32();
  for (int& v : s.status) v = r.i32();
  return s;
}

void write_shape(Writer& w, const std::vector<std::size_t>& shape) {
  w.u32(static_cast<std::uint32_t>(shape.size()));
  for (auto d : shape) w.u64(d);
}

std::vector<std::size_t> read_shape(Reader& r) {
  const std::uint32_t rank = r.u32();
  if (rank > 8) throw Damage("FORMAT");
  std::vector<std::size_t> shape;
  std::uint64_t count = 1;
  for (std::uint32_t k = 0; k < rank; ++k) {
    const std::uint64_t d = r.u64();
    if (d != 0 && count > (std::uint64_t(1) << 40) / d) throw Damage("FORMAT");
    count *= d;
    shape.push_back(static_cast<std::size_t>(d));
  }
  return shape;
}

void write_values(Writer& w, const Ravel& values) {
  w.u64(values.size());
  for (double v : values) w.f64(v);
}

Ravel read_values(Reader& r) {
  const std::uint64_t n = r.u64();
  if (n > r.left() / sizeof(double)) throw Damage("FORMAT");
  Ravel values(static_cast<std::size_t>(n));
  for (double& v : values) v = r.f64();
  return values;
}

void write_change(Writer& w, const ArrayChange& c) {
  w.u8(c.whole ? 1 : 0);
  write_shape(w, c.shape_before);
  write_shape(w, c.shape_after);
  if (!c.whole) {
    w.u32(static_cast<std::uint32_t>(c.ranges.size()));
    for (const auto& [first, end] : c.ranges) {
      w.u64(first);
      w.u64(end);
    }
  }
  write_values(w, c.before);
  write_values(w, c.after);
}

ArrayChange read_change(Reader& r) {
  ArrayChange c;
  const std::uint8_t whole = r.u8();
  if (whole > 1) throw Damage("FORMAT");
  c.whole = whole == 1;
  c.shape_before = read_shape(r);
  c.shape_after = read_shape(r);
  if (!c.whole) {
    const std::uint32_t n = r.u32();
    if (n > r.left() / 16) throw Damage("FORMAT");
    for (std::uint32_t k = 0; k < n; ++k) {
      const std::uint64_t first = r.u64(), end = r.u64();
      c.ranges.emplace_back(static_cast<std::size_t>(first), static_cast<std::size_t>(end));
    }
  }
  c.before = read_values(r);
  c.after = read_values(r);
  return c;
}

// The generation of state k (before steps[k], after steps[k - 1]).
std::uint64_t generation_of(std::span<const JournalStep> steps, std::size_t k) {
  return k < steps.size() ? steps[k].generation_before : steps[k - 1].generation_after;
}

const void* identity(const ImageRef& image) {
  return image.watch().lock().get();
}

}  // namespace

std::string encode_journal(const Journal& journal, const Workspace& ws) {
  return encode_journal(journal, images_of(ws));
}

std::string encode_journal(const Journal& journal, const ImageSlots& slots) {
  const std::span<const JournalStep> steps = journal.steps();
  const std::size_t position = journal.position();
  if (steps.empty()) return {};

  // How each image is kept, for the states first .. last; a step whose image can be kept in no
  // way is left out with every step beyond it (further from the current state).
  struct Kept {
    ImageKind kind = no_image;
    std::uint32_t number = 0;  // the slot, or the state (counted from `first`)
    Description desim;
    std::string bytes;  // stored: the image as IGDSIMAG's payload encodes it
  };
  std::size_t first = 0, last = steps.size();
  std::vector<ImageRef> order;
  std::map<const void*, Kept> kept;
  for (;;) {
    order.clear();
    kept.clear();
    std::size_t stored = 0;
    std::map<std::uint64_t, std::size_t> state_of;
    for (std::size_t k = last + 1; k-- > first;) state_of[generation_of(steps, k)] = k - first;
    auto keep = [&](const ImageRef& image) -> bool {
      if (!image) return true;
      const void* id = identity(image);
      if (auto known = kept.find(id); known != kept.end()) return known->second.kind != no_image;
      Kept k;
      for (std::size_t s = 0; s < slots.size() && k.kind == no_image; ++s) {
        if (slots[s] == image) {
          k.kind = slot_image;
          k.number = static_cast<std::uint32_t>(s);
        }
      }
      // An image made only now (one the session brought back by recipe) that the kernels
      // refuse to draw cannot be kept: the steps that need it are left out.
      try {
        if (k.kind == no_image) {
          if (auto recipe = journal.recipe_of(image)) {
            if (auto state = state_of.find(recipe->first); state != state_of.end()) {
              k.kind = recipe_image;
              k.number = static_cast<std::uint32_t>(state->second);
              k.desim = recipe->second;
            }
          }
        }
        if (k.kind == no_image) {
          Writer w;
          w.image(*image);
          if (w.size() <= journal_image_limit && stored + w.size() <= journal_images_limit) {
            k.kind = stored_image;
            k.bytes = w.str();
            stored += w.size();
          }
        }
      } catch (const DataError&) {
        k = Kept{};
      }
      const bool ok = k.kind != no_image;
      kept.emplace(id, std::move(k));
      if (ok) order.push_back(image);
      return ok;
    };
    std::size_t values = 0;
    auto step_kept = [&](const JournalStep& s) {
      // The session file is written again after every change: a step that replaced large
      // arrays whole stays in memory only.
      const std::size_t bytes = s.inppn.bytes() + s.inptg.bytes();
      if (bytes > journal_step_limit || values + bytes > journal_values_limit) return false;
      values += bytes;
      bool ok = true;
      for (const auto* images : {&s.images_before, &s.images_after})
        for (const ImageRef& image : *images) ok = keep(image) && ok;
      return ok;
    };
    // From the current state outwards, so that the steps nearest it are kept first.
    std::size_t new_first = first, new_last = last;
    for (std::size_t k = position; k-- > first;) {
      if (!step_kept(steps[k])) {
        new_first = k + 1;
        break;
      }
    }
    for (std::size_t k = position; k < last; ++k) {
      if (!step_kept(steps[k])) {
        new_last = k;
        break;
      }
    }
    if (new_first == first && new_last == last) break;
    first = new_first;
    last = new_last;
  }
  if (first == last) return {};

  std::map<const void*, std::uint32_t> number;
  Writer w;
  w.u32(journal_version);
  w.u32(static_cast<std::uint32_t>(last - first));
  w.u32(static_cast<std::uint32_t>(position - first));
  w.u32(static_cast<std::uint32_t>(order.size()));
  for (const ImageRef& image : order) {
    const Kept& k = kept.at(identity(image));
    number[identity(image)] = static_cast<std::uint32_t>(number.size() + 1);
    w.u8(k.kind);
    if (k.kind == stored_image) {
      w.u64(k.bytes.size());
      w.bytes(k.bytes);
    } else {
      w.u32(k.number);
      if (k.kind == recipe_image) w.description(k.desim);
    }
  }
  for (std::size_t k = first; k < last; ++k) {
    const JournalStep& s = steps[k];
    w.u32(static_cast<std::uint32_t>(s.name.size()));
    w.bytes(s.name);
    write_settings(w, s.before);
    write_settings(w, s.after);
    write_change(w, s.inppn);
    write_change(w, s.inptg);
    for (const auto* images : {&s.images_before, &s.images_after})
      for (const ImageRef& image : *images) w.u32(image ? number.at(identity(image)) : 0);
  }
  return w.str();
}

Journal decode_journal(std::string_view bytes, const Workspace& ws, std::array<bool, 3> lost) {
  Reader r(bytes);
  if (r.u32() != journal_version) throw Damage("FORMAT");
  const std::uint32_t count = r.u32(), position = r.u32();
  if (count > Journal::max_steps || position > count) throw Damage("FORMAT");
  struct Entry {
    ImageKind kind;
    std::uint32_t number = 0;
    Description desim;
    ImageRef image;
  };
  // Each count is checked before anything is made of that size: the steps name six images
  // each, so the table holds no more than that.
  const std::uint32_t image_count = r.u32();
  if (image_count > 6 * std::size_t(count) || image_count > r.left() / 5) throw Damage("FORMAT");
  std::vector<Entry> entries(image_count);
  const ImageSlots slots = images_of(ws);
  for (Entry& e : entries) {
    const std::uint8_t kind = r.u8();
    if (kind < slot_image || kind > stored_image) throw Damage("FORMAT");
    e.kind = static_cast<ImageKind>(kind);
    if (e.kind == stored_image) {
      const std::uint64_t n = r.u64();
      if (n > journal_image_limit) throw Damage("FORMAT");
      Reader image_reader(r.bytes(static_cast<std::size_t>(n)));
      auto image = std::make_shared<Image>(image_reader.image(journal_image_limit / 8));
      image_reader.finish();
      if (auto p = image_problem(*image)) throw Damage("IMAGE: " + p->reason);
      e.image = std::shared_ptr<const Image>(std::move(image));
      continue;
    }
    e.number = r.u32();
    if (e.kind == slot_image) {
      if (e.number >= slots.size() || (!slots[e.number] && !lost[e.number])) throw Damage("FORMAT");
      e.image = slots[e.number];
    } else {
      if (e.number > count) throw Damage("FORMAT");
      e.desim = r.description();
      Image probe;
      probe.desim = e.desim;
      if (auto p = image_problem(probe)) throw Damage("IMAGE: " + p->reason);
    }
  }
  std::vector<JournalStep> steps(count);
  std::vector<std::array<std::uint32_t, 6>> images(count);
  for (std::uint32_t k = 0; k < count; ++k) {
    JournalStep& s = steps[k];
    const std::uint32_t n = r.u32();
    if (n == 0 || n > max_name_bytes) throw Damage("FORMAT");
    s.name = std::string(r.bytes(n));
    // A name is printed to the terminal: a command's words, nothing else.
    for (char c : s.name)
      if (!((c >= 'A' && c <= 'Z') || c == ' ')) throw Damage("FORMAT");
    s.before = read_settings(r);
    s.after = read_settings(r);
    s.inppn = read_change(r);
    s.inptg = read_change(r);
    for (std::uint32_t& i : images[k]) {
      i = r.u32();
      if (i > entries.size()) throw Damage("FORMAT");
    }
  }
  r.finish();

  Journal journal;
  if (auto p = journal.rebuild(ws, std::move(steps), position)) throw Damage("JOURNAL: " + *p);
  // Images drawn from a state: made when first looked at, from that state's inputs, which are
  // made again then from the steps (one copy of the inputs however many states are named).
  std::shared_ptr<const JournalStates> states;
  for (Entry& e : entries) {
    if (e.kind != recipe_image) continue;
    if (!states) states = std::make_shared<const JournalStates>(journal, ws);
    const std::size_t k = e.number;
    if (states->settings_of(k).nocur <= 0) throw Damage("JOURNAL: IMAGE OF NO SURFACE");
    const std::uint64_t generation = states->generation_of(k);
    e.image = image_by_recipe([states, k] { return states->inputs_of(k); }, generation, e.desim);
    journal.remember(e.image, generation, e.desim);
  }
  std::span<JournalStep> filled = journal.steps_to_complete();
  for (std::size_t k = 0; k < filled.size(); ++k) {
    for (std::size_t i = 0; i < 6; ++i) {
      const std::uint32_t n = images[k][i];
      ImageRef image = n == 0 ? ImageRef{} : entries[n - 1].image;
      (i < 3 ? filled[k].images_before : filled[k].images_after)[i % 3] = image;
    }
  }
  return journal;
}

}  // namespace igds::disk
