// The IGDS workspace variables (manual section 7, docs/interp.md, "END APL"): the whole session.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "workspace/drawing/drawing.h"
#include "workspace/kernels/array.h"
#include "workspace/kernels/project.h"
#include "workspace/kernels/surface.h"

namespace igds {

// DESIM: what an image shows and how it was projected.
struct Description {
  // DESIM[1]: 0 input points, 1 surface, 2 a DUCT picture (DISPLAY PICTURE), 3 the surface with
  // its curvature combs (DISPLAY COMBS)
  int what = 0;
  Projection projection = Projection::orthogonal;  // DESIM[2]
  std::array<double, 3> parameters{};  // DESIM[3 4 5]: view point, angles, axis+angle, plane
  // DISPLAY HIDDEN: a surface image drawn without what the surface hides. Not one of
  // DESIM's five numbers (the manual has no such image); kept beside them (docs/disk.md).
  bool hidden = false;
  friend bool operator==(const Description&, const Description&) = default;
};

// The picture of DISPLAY PICTURE: the DUCT picture file's text (docs/exchange.md), which is what is
// kept on the disk, and the drawing it makes seen as `desim` says, made once when the image is
// made (workspace/images.h picture_image).
struct ImagePicture {
  std::string name;  // NAME of NAME.DUCTPIC
  std::string text;
  Description desim;
  Drawing2 drawing;
};

// A projected image: IMAGE with its DESIM (or TEMP1/DEST1, TEMP2/DEST2).
struct Image {
  Description desim;
  // IMAGE: planes x rows x 2, one plane per curve: NOCUR x NOSTR x 2 for an input image, the
  // shape of INTPN with 2 columns for a surface image.
  Array points;
  // Input images only: one row per non-zero border tangent, k x 6: the projected base point (x y)
  // and the projected tangent vector (dx dy), in the units of `points`, then the point number
  // and 1 (along the curve) or 0 (along the stringer). Drawn as arrows. (Files written before the
  // last two columns existed have k x 4.)
  Array arrows;
  // DISPLAY COMBS only: planes x rows x 4, the projected ends of the combs of each point of
  // `points`, along its curve (x y) then along its stringer (x y); and the comb's length in space
  // per unit of curvature (docs/kernels.md, "Curvature"). Empty when IMAGE was assigned in APL.
  Array combs;
  double comb_scale = 0;
  // The generation of the surface this image is a projection of (Changes::surface), when it can
  // be made again from that surface and `desim` alone; 0 otherwise (an image read from a file or
  // assigned in the APL environment). The session saves such an image as that recipe.
  std::uint64_t drawn_from = 0;
  // DISPLAY FILE: the IGDSIMAG file the image was read from and the checksum that file ends with
  // (the session keeps a second name of that file instead of writing the image again).
  std::filesystem::path file;
  std::uint64_t file_sum = 0;
  // DESIM[1] = 2 only: the picture (IMAGE is then empty: the picture is not a grid).
  std::shared_ptr<const ImagePicture> picture;
  // ZOOM: the part shown, corners x0 y0 x1 y1 (x0 < x1, y0 < y1) in the units of `points`;
  // nullopt: the whole image. A way of looking at the image, not kept on the disk
  // (docs/decisions.md).
  std::optional<std::array<double, 4>> window;
  // The box of `points`, x0 y0 x1 y1, when the projection that made them found it, or the check of
  // the file they were read from (DISPLAY FILE, the session's images at start): a picture of
  // millions of points is then fitted to a device without reading them again. Whatever replaces
  // `points` clears it (an image assigned in APL); nullopt: not known.
  std::optional<std::array<double, 4>> extent;
  // An input image of a surface whose border tangents were set by AUTO: its description says so.
  bool auto_tangents = false;
  // A hidden-line image (desim.hidden): how near each point of `points` is to the eye, planes x
  // rows (workspace/kernels/hidden.h), from which the picture finds what the surface hides.
  Array nearness;
  // The memory its points, arrows, nearness and combs hold.
  std::size_t bytes() const {
    return (points.size() + arrows.size() + nearness.size() + combs.size()) * sizeof(double);
  }
  // Equal images show the same: how they were made is not compared.
  friend bool operator==(const Image& a, const Image& b) {
    const bool same_picture =
        a.picture == b.picture || (a.picture && b.picture && a.picture->name == b.picture->name &&
                                   a.picture->text == b.picture->text);
    return a.desim == b.desim && a.points == b.points && a.arrows == b.arrows && same_picture &&
           a.window == b.window && a.nearness == b.nearness && a.combs == b.combs &&
           a.comb_scale == b.comb_scale;
  }
};

// An image never changes once made: the workspace shares it (STORE FIRST keeps the same image,
// the screen and the drawing read its points without a copy). An image the session or the undo
// journal keeps by its recipe (workspace/disk/session.cpp) is made when it is first looked at,
// once: an image nobody looks at again costs nothing.
class ImageRef {
 public:
  ImageRef() = default;
  ImageRef(std::nullptr_t) {}
  ImageRef(std::shared_ptr<const Image> image);  // NOLINT: an image is an ImageRef
  // An image that `make` makes when it is first looked at, drawn from the surface of generation
  // `drawn_from` with `desim` (what make's image will say).
  static ImageRef deferred(std::function<Image()> make, std::uint64_t drawn_from,
                           const Description& desim);

  const Image& operator*() const { return get(); }
  // The image as a shared pointer (a drawing that reads its points keeps it alive).
  std::shared_ptr<const Image> shared() const {
    get();
    return cell_->image;
  }
  const Image* operator->() const { return &get(); }
  explicit operator bool() const { return cell_ != nullptr; }
  void reset() { cell_.reset(); }
  // False while a deferred image has not been made yet.
  bool made() const { return cell_ && cell_->image; }
  // The surface's generation and the DESIM it was drawn with, for an image drawn from a surface
  // (Image::drawn_from not 0); known of a deferred image without making it.
  std::optional<std::pair<std::uint64_t, Description>> recipe() const;
  // True when both are drawn from the same surface with the same DESIM and shown through the
  // same window: equal images (one function makes them, bit for bit), known without making or
  // comparing their points.
  bool same_recipe(const ImageRef& other) const;
  // The same image (not only equal ones).
  friend bool operator==(const ImageRef& a, const ImageRef& b) { return a.cell_ == b.cell_; }
  // A weak hold on this image, for telling later whether an ImageRef is still it.
  std::weak_ptr<const void> watch() const { return cell_; }
  bool is(const std::weak_ptr<const void>& watched) const {
    return cell_ && !watched.expired() && watched.lock().get() == cell_.get();
  }

 private:
  // Shared by every ImageRef of the image; made once, by the first look.
  struct Cell {
    mutable std::shared_ptr<const Image> image;
    mutable std::function<Image()> make;  // until the image is made
    std::uint64_t drawn_from = 0;         // of a deferred image
    Description desim;
  };
  const Image& get() const;
  std::shared_ptr<const Cell> cell_;
};

// The same images, or equal ones.
inline bool same_image(const ImageRef& a, const ImageRef& b) {
  return a == b || (a && b && (a.same_recipe(b) || *a == *b));
}

// The parts of an array changed since the session last saved it: the autosave writes those
// (workspace/disk/session.cpp) instead of comparing the whole array with a copy.
struct Edits {
  bool whole = true;                                        // all of it (or its shape)
  std::vector<std::pair<std::size_t, std::size_t>> ranges;  // else these [first, end) of the ravel
  void all() {
    whole = true;
    ranges.clear();
  }
  void part(std::size_t first, std::size_t end) {
    if (whole) return;
    ranges.emplace_back(first, end);
    if (ranges.size() > 4096) all();  // beyond that, rewriting it whole costs less
  }
  void saved() {
    whole = false;
    ranges.clear();
  }
  // Adds the changes of `other`.
  void add(const Edits& other) {
    if (other.whole) return all();
    for (const auto& [first, end] : other.ranges) part(first, end);
  }
  // Nothing changed yet (the start of an edit).
  static Edits none() {
    Edits e;
    e.saved();
    return e;
  }
};

// A number never given before in this process: the generations of surfaces.
std::uint64_t new_generation();

// What changed in the surface, kept by whoever changes it (commands/surface.h, RESTORE, the APL
// environment) for the autosave and for the images drawn from it.
struct Changes {
  // A new number after every change of NOCUR ... INTPN (Image::drawn_from refers to it); every
  // workspace starts with a number of its own.
  std::uint64_t surface = new_generation();
  // PATCHES and INTPN are the interpolation of the inputs by igds's kernels (false once the APL
  // environment assigned one of them): the session does not save them then, it computes them
  // again at start. Such a surface keeps no PATCHES either (patches_of below).
  bool derived = true;
  Edits inppn, inptg;

  // The whole surface was replaced (BUILD, RESTORE).
  void replaced(bool interpolated = true) {
    surface = new_generation();
    derived = interpolated;
    inppn.all();
    inptg.all();
  }
  // The inputs edited in place and interpolated again (CHANGE): `points` and `tangents` say
  // which parts of INPPN and INPTG changed.
  void edited(const Edits& points, const Edits& tangents) {
    surface = new_generation();
    derived = true;
    inppn.add(points);
    inptg.add(tangents);
  }
};

// A variable of the user's own in END APL (not one of the manual's): its name (as APL folds it:
// capitals, digits, _ ∆ ⍙ in UTF-8), its shape and its elements, numbers or characters.
struct AplVariable {
  std::string name;
  std::vector<std::size_t> shape;
  bool characters = false;
  std::vector<double> numbers;  // when !characters
  std::u32string text;          // when characters
  friend bool operator==(const AplVariable&, const AplVariable&) = default;
};

// The tangents and twists of a surface's interpolation (kernels/surface.h), kept with it: its
// PATCHES are made from them and the points when read (kept_splines below), without solving the
// splines again. They belong to one generation of the surface (Changes::surface): any change of
// the inputs makes a new generation, and they are no longer read.
struct KeptSplines {
  std::uint64_t surface = 0;
  std::shared_ptr<const SplineTangents> made;
};

struct Workspace {
  int nocur = 0, nostr = 0;  // NOCUR, NOSTR: input curves and stringers (0: no input yet)
  int intcu = 0, intst = 0;  // INTCU, INTST: curves/stringers interpolated between input ones
  Array inppn;               // INPPN: (NOCUR*NOSTR) x 3, in point-number order
  // INPTG: 2(NOCUR+NOSTR) x 4 border tangents x y z and point number. Rows in this order: the
  // tangents along the curves at the ends of each curve (curve 1 place 1, curve 1 place NOSTR,
  // curve 2 place 1, ...), then the tangents along the stringers at the ends of each stringer
  // (stringer 1 curve 1, stringer 1 curve NOCUR, stringer 2 curve 1, ...). Corners appear twice.
  Array inptg;
  // PATCHES: (NOCUR-1) x (NOSTR-1) x 3 x 4 x 4, kept only when they are not the interpolation's
  // (Changes::derived false: FIT's, END APL's); else without a shape, or the empty array of a
  // single curve or stringer, and read through patches_of.
  Array patches;
  Array intpn;     // INTPN: (NOCUR+INTCU(NOCUR-1)) x (NOSTR+INTST(NOSTR-1)) x 3
  ImageRef image;  // IMAGE / DESIM: the current image
  ImageRef temp1;  // TEMP1 / DEST1: STORE FIRST
  ImageRef temp2;  // TEMP2 / DEST2: STORE SECOND
  // STATUS[1] = 1 for HELP LONG, 0 for SHORT; STATUS[2] = keyboard of the last PLOT
  // (0 none yet, 1 SELECTRIC, 2 EBCDIC); STATUS[3] and STATUS[4] belong to the surface
  // (status_twists, status_auto below); the others are reserved.
  std::array<int, 10> status{1, 0, 0, 0, 0, 0, 0, 0, 0, 0};
  // The functions defined in END APL, each as its source (header, then lines), and the user's
  // variables there: the APL workspace, kept with the session.
  std::vector<std::vector<std::string>> functions;
  std::vector<AplVariable> apl_variables;

  Changes changes;      // not a variable of the manual: how the variables above changed
  KeptSplines splines;  // nor this: made from the inputs

  // STATUS[3]: the twists of the surface's patches, 0 ZERO (the manual's), 1 MARKS (CHANGE
  // TWISTS; docs/marks.md). STATUS[4]: 1 when its border tangents were set by AUTO.
  static constexpr std::size_t status_twists = 2, status_auto = 3;
  bool marks_twists() const { return status[status_twists] == 1; }
  bool auto_tangents() const { return status[status_auto] == 1; }
  void set_surface_modes(bool marks, bool automatic) {
    status[status_twists] = marks ? 1 : 0;
    status[status_auto] = automatic ? 1 : 0;
  }

  bool has_input() const { return nocur > 0; }
  bool has_surface() const { return !intpn.empty(); }
  friend bool operator==(const Workspace& a, const Workspace& b) {
    return a.nocur == b.nocur && a.nostr == b.nostr && a.intcu == b.intcu && a.intst == b.intst &&
           a.inppn == b.inppn && a.inptg == b.inptg && a.patches == b.patches &&
           a.intpn == b.intpn && same_image(a.image, b.image) && same_image(a.temp1, b.temp1) &&
           same_image(a.temp2, b.temp2) && a.status == b.status && a.functions == b.functions &&
           a.apl_variables == b.apl_variables;
  }
};

// What the kernels interpolate for the surface of `ws`: its inputs, density and twists.
inline SurfaceInput surface_input(const Workspace& ws) {
  return {ws.nocur, ws.nostr, ws.intcu, ws.intst, &ws.inppn, &ws.inptg, ws.marks_twists()};
}

// True when the surface of `ws` is the interpolation of its inputs and keeps no PATCHES: only a
// few commands read them (docs/kernels.md), which make them from the inputs.
inline bool patches_made_when_read(const Workspace& ws) {
  return ws.changes.derived && ws.patches.size() == 0 && ws.nocur > 1 && ws.nostr > 1 &&
         ws.has_surface();
}

// Keeps `made`, the tangents and twists the surface of `ws` was just interpolated with, once its
// generation is set.
inline void keep_splines(Workspace& ws, std::shared_ptr<const SplineTangents> made) {
  ws.splines = {ws.changes.surface, std::move(made)};
}

// The tangents and twists PATCHES are made from, when the surface of `ws` keeps those of its own
// inputs (else null: they are made again).
inline std::shared_ptr<const SplineTangents> kept_splines(const Workspace& ws) {
  const SplineTangents* made = ws.splines.made.get();
  if (!made || ws.splines.surface != ws.changes.surface || !patches_made_when_read(ws) ||
      made->tangents.along_curves.size() != ws.inppn.size() / 3 ||
      made->twists.empty() == ws.marks_twists())
    return nullptr;
  return ws.splines.made;
}

// PATCHES of the surface of `ws`: those it keeps, or made into `made` from the inputs
// (patches_made_when_read), bit for bit those the interpolation evaluated.
inline const Array& patches_of(const Workspace& ws, Array& made) {
  if (!patches_made_when_read(ws)) return ws.patches;
  made = surface_patches(surface_input(ws), kept_splines(ws));
  return made;
}

// PATCHES kept in the workspace from now on, made first if need be (END APL: the patches of the
// inputs before an input changes).
inline void keep_patches(Workspace& ws) {
  Array made;
  if (&patches_of(ws, made) == &made) ws.patches = std::move(made);
}

// A surface that is the interpolation of its inputs keeps no PATCHES (those of a single curve or
// stringer hold no number and stay): after a kernel kept them, to compare them with a file's.
inline void drop_derived_patches(Workspace& ws) {
  if (ws.changes.derived && ws.patches.size() > 0) ws.patches = Array();
}

}  // namespace igds
