// The undo journal (issue 14): the states of the workspace after each command that changed it,
// for UNDO and REDO. A state is the surface's inputs and modes (Settings), INPPN and INPTG, the
// images IMAGE TEMP1 TEMP2 and STATUS; PATCHES and INTPN are made again from the inputs, never
// kept. A step keeps only what its command changed: the edited ranges of INPPN and INPTG (from
// Changes' Edits) with their values before and after, and the images, which are shared. The
// session keeps the journal on the disk (workspace/disk/journal_file.h, docs/disk.md).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "workspace/state.h"

namespace igds {

// The numbers of a state that UNDO puts back besides INPPN, INPTG and the images. A mode added
// to the surface is one more field here, in of(), apply_to() and journal_file.cpp's encoding.
struct Settings {
  int nocur = 0, nostr = 0, intcu = 0, intst = 0;
  std::array<int, 10> status{};

  static Settings of(const Workspace& ws);
  void apply_to(Workspace& ws) const;
  friend bool operator==(const Settings&, const Settings&) = default;
};

// How one input array (INPPN or INPTG) differs between two states.
struct ArrayChange {
  std::vector<std::size_t> shape_before, shape_after;
  // Whole: `before` and `after` are the two ravels. Else the ravel keeps its shape and `ranges`
  // ([first, end), sorted, apart) are the parts that changed, their values in `before` and
  // `after`, one range after the other.
  bool whole = false;
  std::vector<std::pair<std::size_t, std::size_t>> ranges;
  Ravel before, after;

  bool unchanged() const { return !whole && ranges.empty(); }
  std::size_t bytes() const;
  // `a` (the array as it was before, or after) made as it is after (before); false when the
  // change does not fit `a` (a journal read from the disk is checked with it).
  bool forward(Array& a) const;
  bool backward(Array& a) const;
};

using ImageSlots = std::array<ImageRef, 3>;  // IMAGE, TEMP1, TEMP2
ImageSlots images_of(const Workspace& ws);

// One command's change: from the state before it to the state after it.
struct JournalStep {
  std::string name;  // the command and its option, e.g. "CHANGE POINTS"
  Settings before, after;
  ArrayChange inppn, inptg;
  ImageSlots images_before, images_after;
  // Changes::surface of the two states (in memory only: images drawn from them are recipes).
  std::uint64_t generation_before = 0, generation_after = 0;

  std::size_t bytes() const;
};

class Journal {
 public:
  // Bounds: the steps kept, and the bytes of their values (the oldest steps go first). A step
  // larger than max_bytes alone cannot be undone: the journal starts again after it.
  static constexpr std::size_t max_steps = 200;
  static constexpr std::size_t max_bytes = 4u << 20;
  // The images only the journal still holds (drawn earlier, replaced since): one surface image of
  // 4 M points (64 MB), so that a session with a command's scratch stays within twice its
  // variables (docs/disk.md, "The undo journal").
  static constexpr std::size_t max_image_bytes = 64u << 20;

  Journal() = default;
  // `ws` is the current state; nothing to undo or redo.
  explicit Journal(const Workspace& ws);

  // After a command: when `ws` is not the current state any more, a step named `name` from the
  // current state to `ws`, which becomes current; the steps that REDO would have made again are
  // dropped. True when a step was recorded. Reads ws.changes (the Edits since the last save, a
  // superset of those since the current state) before the session resets them.
  bool record(const Workspace& ws, std::string_view name);

  // UNDO and REDO: `ws` made the state before (after) the step, PATCHES and INTPN made again from
  // its inputs, ws.changes saying what changed (for the autosave). The step's name, or nullopt
  // when there is nothing to undo (redo). Throws DataError when the surface cannot be interpolated
  // (never for a state that was current once); `ws` is unchanged then.
  std::optional<std::string> undo(Workspace& ws);
  std::optional<std::string> redo(Workspace& ws);

  std::size_t undo_count() const { return position_; }
  std::size_t redo_count() const { return steps_.size() - position_; }
  // The bytes of the values the steps keep (what the bounds count).
  std::size_t bytes() const { return bytes_; }
  std::span<const JournalStep> steps() const { return steps_; }
  // Steps [0, position) are undone by UNDO, last first; [position, end) made again by REDO.
  std::size_t position() const { return position_; }

  // A journal read from the disk: `steps` around the current state `ws` (the state after
  // steps[position - 1], before steps[position]). Checks that every step fits the state it
  // starts from and that every state is a surface igds accepts (workspace/variables.h); returns
  // the problem, in the words of a report's reason, and leaves the journal as it was then.
  std::optional<std::string> rebuild(const Workspace& ws, std::vector<JournalStep> steps,
                                     std::size_t position);
  // The steps' images set (once rebuild() gave the states they are drawn from).
  std::span<JournalStep> steps_to_complete() { return steps_; }

  // The surface (Changes::surface) and DESIM an image is drawn from, when it can be made again
  // from them: an image made again from a state of a journal read from the disk is remembered
  // here, so that saving it again does not make it.
  void remember(const ImageRef& image, std::uint64_t generation, const Description& desim);
  std::optional<std::pair<std::uint64_t, Description>> recipe_of(const ImageRef& image) const;

 private:
  void apply(Workspace& ws, const JournalStep& step, bool back);
  void bound();
  // The bytes of the images the steps hold that are not in the workspace's slots now.
  std::size_t held_image_bytes() const;

  std::vector<JournalStep> steps_;
  std::size_t position_ = 0;
  std::size_t bytes_ = 0;
  // The current state: settings, inputs, images and generation, as the last step left them.
  struct State {
    Settings settings;
    Array inppn, inptg;
    std::uint64_t generation = 0;
  };
  State current_;
  ImageSlots images_;
  struct Remembered {
    std::weak_ptr<const void> image;
    std::uint64_t generation;
    Description desim;
  };
  std::vector<Remembered> remembered_;
};

// The inputs of the states of a journal just read from the disk (Journal::rebuild), made again
// when one is wanted (an image drawn from that state is first made): from the state current at
// the reading and the steps' changes, so that a journal naming many states holds their changes
// and one copy of the inputs, not a copy of INPPN for each.
class JournalStates {
 public:
  JournalStates(const Journal& journal, const Workspace& ws);
  std::size_t count() const { return steps_.size() + 1; }
  // State k (0: before the first step, k: after step k - 1): its settings, INPPN and INPTG, and
  // its generation in changes.surface (an image drawn from it is that recipe).
  Workspace inputs_of(std::size_t k) const;
  const Settings& settings_of(std::size_t k) const;
  std::uint64_t generation_of(std::size_t k) const;

 private:
  struct Change {
    Settings before, after;
    ArrayChange inppn, inptg;
    std::uint64_t generation_before = 0, generation_after = 0;
  };
  Settings settings_;
  Array inppn_, inptg_;
  std::uint64_t generation_ = 0;
  std::size_t position_ = 0;
  std::vector<Change> steps_;
};

}  // namespace igds
