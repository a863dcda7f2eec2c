#include "workspace/images.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <optional>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "workspace/drawing/project.h"
#include "workspace/exchange/duct.h"
#include "workspace/kernels/curvature.h"
#include "workspace/kernels/data_error.h"
#include "workspace/kernels/fit.h"
#include "workspace/kernels/hidden.h"
#include "workspace/kernels/parallel.h"
#include "workspace/kernels/surface.h"

namespace igds {

namespace {

// The points projected (the view point of a conic projection must lie outside them, workspace/
// kernels/project.h project_image), the first whose image is not finite (points.size(): none) and
// the box of the images.
std::pair<Array, ProjectedImage> projected(Vec3View points, std::vector<std::size_t> shape,
                                           const View& view, Vec3 centre,
                                           bool box_of_points = false) {
  // Every point's image is written by the projection (or the array dropped): not cleared first.
  Array out = Array::for_output(std::move(shape));
  const ProjectedImage found = project_image(view, centre, points, as_point2(out), box_of_points);
  return {std::move(out), found};
}

// A projection of finite points can overflow (coordinates near the largest numbers, a CONIC eye
// a hair's breadth from a point's plane): the first point `k` whose image is not finite is
// refused, named as the array it was projected from counts it (1-based).
void check_projected(std::size_t k, std::size_t points, const std::string& variable,
                     std::size_t columns) {
  if (k == points) return;
  DataError e(DataError::Problem::image_not_finite);
  e.variable = variable;
  e.number = k / columns + 1;
  e.column = k % columns + 1;
  throw e;
}

// Images of the current surface can be made again from it: they remember its generation.
std::uint64_t recipe_of(const Workspace& ws, bool needs_derived) {
  return needs_derived && !ws.changes.derived ? 0 : ws.changes.surface;
}

}  // namespace

Image input_image(const Workspace& ws, const View& view) {
  auto points = as_vec3(ws.inppn);
  const Vec3 centre = bounding_box_centre(points);
  Image image;
  image.desim = {0, view.projection, view.parameters};
  ProjectedImage found;
  std::tie(image.points, found) =
      projected(points, {static_cast<std::size_t>(ws.nocur), static_cast<std::size_t>(ws.nostr), 2},
                view, centre);

  // The diagonal of the bounding box sets the step of the numerical derivative.
  Vec3 low = points.empty() ? Vec3{} : points[0], high = low;
  for (Vec3 p : points) {
    low = {std::min(low.x, p.x), std::min(low.y, p.y), std::min(low.z, p.z)};
    high = {std::max(high.x, p.x), std::max(high.y, p.y), std::max(high.z, p.z)};
  }
  const double size = std::max(norm(high - low), 1e-9);

  Ravel arrows;
  const std::size_t rows = ws.inptg.shape.empty() ? 0 : ws.inptg.shape[0];
  const std::size_t curve_rows = 2 * static_cast<std::size_t>(ws.nocur);
  for (std::size_t r = 0; r < rows; ++r) {
    const double* row = ws.inptg.data() + r * 4;
    const Vec3 t{row[0], row[1], row[2]};
    const double length = norm(t);
    const auto k = static_cast<std::size_t>(row[3]);
    if (length == 0 || k < 1 || k > points.size()) continue;
    // The projection's derivative along T: (proj(P + hT) - proj(P)) / h, with h|T| small
    // against the surface, so that CONIC arrows follow the perspective at their base.
    const double h = 1e-6 * size / length;
    const Vec3 base = points[k - 1], tip = base + h * t;
    const double ends[6] = {base.x, base.y, base.z, tip.x, tip.y, tip.z};
    double p[4];
    project(view, centre, Vec3View(ends, 2), MutablePoint2View(p, 2));
    arrows.insert(arrows.end(), {p[0], p[1], (p[2] - p[0]) / h, (p[3] - p[1]) / h, double(k),
                                 r < curve_rows ? 1.0 : 0.0});
  }
  check_projected(found.not_finite, points.size(), "INPPN", 1);
  image.extent = found.extent;
  for (std::size_t a = 0; a < arrows.size(); a += 6) {
    if (first_not_finite(&arrows[a], 4) == 4) continue;
    DataError e(DataError::Problem::image_not_finite);
    e.variable = "INPTG";
    e.number = static_cast<std::size_t>(arrows[a + 4]);
    throw e;
  }
  if (!arrows.empty()) {
    image.arrows.shape = {arrows.size() / 6, 6};
    image.arrows.ravel = std::move(arrows);
  }
  image.auto_tangents = ws.auto_tangents();
  image.drawn_from = recipe_of(ws, false);
  return image;
}

namespace {

// With `points_box`, the bounding box of INTPN found in the same pass.
Image grid_image(const Workspace& ws, const View& view, bool hidden, Box3* points_box = nullptr) {
  if (ws.intpn.rank() != 3) {
    DataError e(DataError::Problem::missing);
    e.variable = "INTPN";
    throw e;
  }
  auto points = as_vec3(ws.intpn);
  Image image;
  image.desim = {1, view.projection, view.parameters, hidden};
  const Vec3 centre = bounding_box_centre(as_vec3(ws.inppn));
  ProjectedImage found;
  std::tie(image.points, found) = projected(points, {ws.intpn.shape[0], ws.intpn.shape[1], 2}, view,
                                            centre, points_box != nullptr);
  check_projected(found.not_finite, points.size(), "INTPN", ws.intpn.shape[1]);
  if (points_box) *points_box = found.points;
  image.extent = found.extent;
  if (hidden) {
    // Finite wherever the projection is (a CONIC point is in front of the eye).
    image.nearness = Array({ws.intpn.shape[0], ws.intpn.shape[1]});
    nearness(view, centre, points, std::span<double>(image.nearness.data(), image.nearness.size()));
  }
  image.drawn_from = recipe_of(ws, true);
  return image;
}

}  // namespace

Image surface_image(const Workspace& ws, const View& view) {
  return grid_image(ws, view, false);
}

Image hidden_surface_image(const Workspace& ws, const View& view) {
  return grid_image(ws, view, true);
}

double comb_scale_for(double extent, double most) {
  if (!(most > 0) || !(extent > 0) || !std::isfinite(extent / most)) return 0;
  const double target = comb_fraction * extent / most;
  const double decade = std::pow(10.0, std::floor(std::log10(target)));
  for (double step : {5.0, 2.0, 1.0})
    if (step * decade <= target) return step * decade;
  return decade / 2;  // log10 rounded up (target just below a power of ten)
}

namespace {

// The input point where the input lines of one direction bend most sharply, by the circle
// through it and its two neighbours on its line (the squared curvature 4 |a x b|^2 / (|a| |b|
// |c|)^2 of its sides a, b and c): its row of INPPN (`curves` rows of `stringers` points), or none
// where no line has three points that make a circle. The curves when `along` is 1, else the
// stringers (`along` is a row); the points are read in their order.
std::optional<std::size_t> sharpest_input_row(Vec3View points, std::size_t curves,
                                              std::size_t stringers, std::size_t along) {
  // The first and last rows (stringers) or columns (curves) have no neighbour on one side.
  const std::size_t edge_row = along == 1 ? 0 : 1, edge_column = along == 1 ? 1 : 0;
  double most = 0;
  std::optional<std::size_t> at;
  for (std::size_t i = edge_row; i + edge_row < curves; ++i)
    for (std::size_t j = edge_column; j + edge_column < stringers; ++j) {
      const std::size_t m = i * stringers + j;
      const Vec3 p = points[m - along], q = points[m], r = points[m + along];
      const Vec3 a = q - p, b = r - q, c = r - p;
      const double sides = dot(a, a) * dot(b, b) * dot(c, c);
      if (!(sides > 0)) continue;  // two of the points are one
      const Vec3 area = cross(a, b);
      const double bend = 4 * dot(area, area) / sides;
      if (bend > most) most = bend, at = i;
    }
  return at;
}

}  // namespace

std::vector<std::size_t> comb_guess_rows(const Workspace& ws) {
  const GridShape shape = intpn_shape(ws.nocur, ws.nostr, ws.intcu, ws.intst);
  const std::size_t curves = std::size_t(ws.nocur), stringers = std::size_t(ws.nostr);
  const std::size_t patch_rows = std::size_t(ws.intcu) + 1, last_patch = curves - 2;
  std::vector<std::size_t> patches;
  for (std::size_t q = 0; q <= last_patch; q += 8) patches.push_back(q);
  const auto points = as_vec3(ws.inppn);
  for (const std::optional<std::size_t> row :
       {sharpest_input_row(points, curves, stringers, 1),
        sharpest_input_row(points, curves, stringers, stringers)})
    if (row) patches.insert(patches.end(), {*row - (*row > 0), std::min(*row, last_patch)});
  std::sort(patches.begin(), patches.end());
  patches.erase(std::unique(patches.begin(), patches.end()), patches.end());
  std::vector<std::size_t> rows;
  for (const std::size_t q : patches) {
    // A row of patches has the grid's rows from its first to the next one's first; the last
    // also the grid's last row.
    const std::size_t end = q == last_patch ? shape.rows : (q + 1) * patch_rows;
    for (std::size_t row = q * patch_rows; row < end; ++row) rows.push_back(row);
  }
  return rows;
}

namespace {

// The comb scale of combs already drawn from the current surface (an image the workspace holds,
// made): it depends on the surface alone (the box of INTPN and its largest curvature), not on the
// view.
std::optional<double> known_comb_scale(const Workspace& ws) {
  const std::uint64_t surface = recipe_of(ws, true);
  if (surface == 0) return std::nullopt;
  for (const ImageRef* ref : {&ws.image, &ws.temp1, &ws.temp2})
    if (ref->made() && (*ref)->desim.what == 3 && (*ref)->drawn_from == surface)
      return (*ref)->comb_scale;
  return std::nullopt;
}

}  // namespace

Image comb_image(const Workspace& ws, const View& view) {
  // The scale: that of the combs already drawn from this surface, or made from the box of the
  // points (found as their image is made) and the largest curvature (images.h).
  const std::optional<double> known = known_comb_scale(ws);
  Box3 box;
  Image image = grid_image(ws, view, false, known ? nullptr : &box);
  image.desim.what = 3;
  const SurfaceInput in = surface_input(ws);
  const GridShape shape = intpn_shape(ws.nocur, ws.nostr, ws.intcu, ws.intst);
  require_shape("INTPN", &ws.intpn, {shape.rows, shape.cols, 3});
  const std::size_t rows = shape.rows, cols = shape.cols;
  const auto points = as_vec3(ws.intpn);
  // A single curve or stringer's curvature is made whole (CurvatureRows is for grids); a
  // grid's PATCHES are read where the workspace keeps them, or made a row at a time.
  const bool line = ws.nocur == 1 || ws.nostr == 1;
  const Array line_bends = line ? grid_curvature(in, ws.patches) : Array{};
  std::optional<PatchMaker> maker;
  if (!line && patches_made_when_read(ws)) maker.emplace(in, kept_splines(ws));
  const PatchSource* source = maker ? &maker->source() : nullptr;
  // The curvature vectors (6 numbers a point) are made a few rows at a time, on every core, and
  // never kept whole (192 MB at 4 M points): about 8,000 points at a time, whole rows of patches
  // (each made once). `each(part, first, last, curvature)` has rows [first, last) to make with
  // `curvature` (a single line's is made whole first, and read from `line_bends`).
  const unsigned parts = threads_for(6 * points.size());
  const std::size_t patch_rows = std::size_t(ws.intcu) + 1;
  const std::size_t chunk =
      std::max<std::size_t>(1, (std::size_t(1) << 13) / cols / patch_rows) * patch_rows;
  auto by_rows = [&](const auto& each) {
    in_parallel(parts, [&](unsigned part) {
      std::optional<CurvatureRows> curvature;
      if (!line) curvature.emplace(in, ws.patches, source);
      const std::size_t end = rows * (part + 1) / parts;
      for (std::size_t first = rows * part / parts; first < end; first += chunk)
        each(part, first, std::min(end, first + chunk), curvature);
    });
  };
  // Each point's two curvature vectors measured into `largest` and, for a parallel projection,
  // their images written where the point's combs go.
  const bool parallel = view.projection != Projection::conic;
  image.combs = Array::for_output({rows, cols, 4});  // every comb's image is written below
  // A parallel projection is linear (its map has no constant term, kernels/project.h).
  const ProjectiveMap map = parallel ? projection_map(view, {}) : ProjectiveMap{};
  const ProjectiveMap* images_by = parallel ? &map : nullptr;
  auto vectors = [&](std::size_t first, std::size_t last, auto& curvature,
                     LargestCurvature& largest) {
    double* xy = image.combs.data() + 4 * cols * first;
    if (curvature) return curvature->combs(first, last, largest, images_by, xy);
    for (std::size_t k = 0; k < (last - first) * cols; ++k) {
      const double* bends = line_bends.data() + 6 * (first * cols + k);
      comb_vectors(Vec3::load(bends), Vec3::load(bends + 3), images_by, xy + 4 * k, largest);
    }
  };
  // The scale: known, or for CONIC first guessed from a sample of the rows (below), or measured
  // in a pass of its own.
  auto measured_scale = [&](const LargestCurvature& largest) {
    const Vec3 size = box.hi - box.lo;
    return comb_scale_for(std::max({size.x, size.y, size.z}), largest.length());
  };
  auto measure = [&](const auto& rows_of) {
    std::vector<LargestCurvature> found(parts);
    rows_of([&](unsigned part, std::size_t first, std::size_t last, auto& curvature) {
      vectors(first, last, curvature, found[part]);
    });
    LargestCurvature largest;
    for (const LargestCurvature& f : found) largest.add(f);
    return largest;
  };
  const bool guessed = !known && !parallel && !line;
  if (known) {
    image.comb_scale = *known;
  } else if (guessed) {
    // The scale goes by steps of 2 to 2.5 (comb_scale_for), so the largest curvature of the
    // rows that are likeliest to hold it is seldom another's; the combs' pass measures them all,
    // and is made again with the whole's scale where it is.
    const std::vector<std::size_t> sample = comb_guess_rows(ws);
    image.comb_scale = measured_scale(measure([&](const auto& each) {
      in_parallel(parts, [&](unsigned part) {
        std::optional<CurvatureRows> curvature(std::in_place, in, ws.patches, source);
        const std::size_t n = sample.size();
        for (std::size_t k = n * part / parts; k < n * (part + 1) / parts; ++k)
          each(part, sample[k], sample[k] + 1, curvature);
      });
    }));
  } else {
    image.comb_scale = measured_scale(measure(by_rows));
  }
  // The first comb (two a point) whose image is not finite, named by its point of INTPN.
  std::atomic<std::size_t> not_finite{2 * points.size()};
  if (parallel) {
    const double scale = image.comb_scale;
    // The image of a comb's end p - s k is the image of p less s times that of k.
    auto combs = [&](std::size_t first, std::size_t last) {
      const std::size_t bad =
          comb_images(image.points.data() + 2 * cols * first, image.combs.data() + 4 * cols * first,
                      (last - first) * cols, scale);
      if (bad < 2 * (last - first) * cols) keep_least(not_finite, 2 * cols * first + bad);
    };
    if (known) {
      // One pass: the curvature is made once either way (docs/kernels.md, "Curvature").
      by_rows([&](unsigned, std::size_t first, std::size_t last, auto& curvature) {
        LargestCurvature unused;
        vectors(first, last, curvature, unused);
        combs(first, last);
      });
    } else {
      parallel_for(rows, parts, combs);
    }
  } else {
    // The comb's end in space, away from the centre of curvature (so that a comb stands outside
    // the surface's convex side and combs do not cross in a tight bend).
    // CONIC is not linear: the ends are made with s, and projected as they are made. A view
    // point inside the box of all the ends is refused before any other report, as for any image
    // (project_image): a part's own findings are reported after that box is known.
    const Vec3 centre = bounding_box_centre(as_vec3(ws.inppn));
    const Vec3 eye{view.parameters[0], view.parameters[1], view.parameters[2]};
    const ConicFrame frame = conic_frame(eye, centre);  // the surface's image was made with it
    std::vector<ProjectedPart> found_ends(parts);
    std::vector<LargestCurvature> found(parts);
    std::vector<std::vector<double>> line_ends(parts);  // a single line's, in space
    auto ends = [&](unsigned part, std::size_t first, std::size_t last, auto& curvature) {
      const double scale = image.comb_scale;
      const std::size_t n = 2 * (last - first) * cols;
      const double* at = ws.intpn.data() + 3 * cols * first;
      double* xy = image.combs.data() + 4 * cols * first;
      ProjectedPart p;
      if (curvature) {
        p = curvature->conic_combs(first, last, at, scale, frame, eye, xy, found[part]);
      } else {
        std::vector<double>& in_space = line_ends[part];
        in_space.resize(3 * n);
        for (std::size_t k = 0; k < n / 2; ++k) {
          const double* bend = line_bends.data() + 6 * (cols * first + k);
          comb_ends(Vec3::load(at + 3 * k), Vec3::load(bend), Vec3::load(bend + 3), scale,
                    in_space.data() + 6 * k);
        }
        p = project_part(view, centre, Vec3View(in_space.data(), n), MutablePoint2View(xy, n));
      }
      found_ends[part].behind = found_ends[part].behind || p.behind;
      found_ends[part].about_eye.add(p.about_eye);
      if (p.not_finite < n) keep_least(not_finite, 2 * cols * first + p.not_finite);
    };
    by_rows(ends);
    if (guessed) {
      LargestCurvature largest;
      for (const LargestCurvature& f : found) largest.add(f);
      if (const double whole = measured_scale(largest); whole != image.comb_scale) {
        image.comb_scale = whole;
        found_ends.assign(parts, {});
        not_finite = 2 * points.size();
        by_rows(ends);
      }
    }
    Box3 about_eye;
    bool behind = false;
    for (const ProjectedPart& p : found_ends)
      about_eye.add(p.about_eye), behind = behind || p.behind;
    if (about_eye.contains({})) throw DataError(DataError::Problem::view_inside_box);
    if (behind) throw DataError(DataError::Problem::behind_eye);
  }
  if (not_finite.load() < 2 * points.size())
    check_projected(not_finite.load() / 2, points.size(), "INTPN", cols);
  return image;
}

Image picture_image(std::string name, std::string text, const View& view) {
  const Drawing3 drawing = duct_drawing(read_duct(text));
  return picture_image(std::move(name), std::move(text), drawing, view);
}

Image picture_image(std::string name, std::string text, const Drawing3& drawing, const View& view) {
  const Box3 box = bounding_box(drawing);
  const Vec3 centre = box.empty() ? Vec3{} : box.centre();
  if (view.projection == Projection::conic &&
      box.contains({view.parameters[0], view.parameters[1], view.parameters[2]}))
    throw DataError(DataError::Problem::view_inside_box);
  auto picture = std::make_shared<ImagePicture>();
  picture->name = std::move(name);
  picture->text = std::move(text);
  picture->desim = {2, view.projection, view.parameters};
  picture->drawing = project(drawing, view, centre);
  const auto items = picture->drawing.items();
  for (std::size_t n = 0; n < items.size(); ++n) {
    const auto points = picture->drawing.points(items[n]);
    for (std::size_t k = 0; k < points.size(); ++k) {
      if (std::isfinite(points[k].x) && std::isfinite(points[k].y)) continue;
      DataError e(DataError::Problem::image_not_finite);
      e.variable = "DRAWING";
      e.number = n + 1;
      throw e;
    }
  }
  Image image;
  image.desim = picture->desim;
  image.picture = std::move(picture);
  return image;
}

Image image_of(const Workspace& ws, const Description& desim) {
  const View view{desim.projection, desim.parameters};
  return desim.what == 0   ? input_image(ws, view)
         : desim.what == 3 ? comb_image(ws, view)
         : desim.hidden    ? hidden_surface_image(ws, view)
                           : surface_image(ws, view);
}

namespace {

// The image `desim` describes of the surface of the inputs `from`, interpolated first for a
// surface image (and refused when that overflows, as any surface is).
Image made_from(Workspace from, const Description& desim) {
  if (desim.what != 0) {
    Surface s;
    if (auto overflow = interpolate_into(surface_input(from), s, PatchesOut::dropped))
      throw *overflow;
    from.patches = std::move(s.patches);
    from.intpn = std::move(s.intpn);
    from.changes.derived = true;                // its PATCHES are made when read (state.h) ...
    keep_splines(from, std::move(s.tangents));  // ... from these
  }
  return image_of(from, desim);
}

}  // namespace

ImageRef image_by_recipe(std::shared_ptr<const Workspace> source, const Description& desim) {
  const std::uint64_t generation = source->changes.surface;
  return ImageRef::deferred(
      [source = std::move(source), desim] {
        if (desim.what == 0) return image_of(*source, desim);
        return made_from(*source, desim);
      },
      generation, desim);
}

ImageRef image_by_recipe(std::function<Workspace()> source, std::uint64_t generation,
                         const Description& desim) {
  return ImageRef::deferred(
      [source = std::move(source), desim] { return made_from(source(), desim); }, generation,
      desim);
}

}  // namespace igds
