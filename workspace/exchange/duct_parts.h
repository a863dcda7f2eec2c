// What the files of DUCT pictures (duct_*.cpp) share, and no other file: a field trimmed, and the
// layout of a drawing as a picture, which duct_layout.cpp keeps and duct_write.cpp writes as it
// is laid out.
#pragma once

#include <string_view>

#include "workspace/exchange/duct.h"

namespace igds::duct {

// `s` without the blanks and tabs on either side.
inline std::string_view trimmed(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
  return s;
}

// Where the layout's pixels go, in file order.
class PixelSink {
 public:
  // The shape factor T of the pixel that follows (a conic arc's mid pixel; the others have 0).
  virtual void shape(double s) = 0;
  virtual void pixel(Vec3 v) = 0;

 protected:
  ~PixelSink() = default;
};

// The picture of a drawing (a drawing in the plane at z = 0) as duct_picture makes it, without
// its pixels (xyz and tu are left empty): they go to `pixels` when it is given. With `measure`
// (the first walk over a drawing), R1..R6 are the drawing's box and a point that is not finite
// throws DataError before any pixel of its item is handed on; without (the second walk, for the
// pixels), R1..R6 are zero and nothing is checked.
template <class P>
DuctPicture lay_out(const Drawing<P>& drawing, const DuctHeader& header, const DuctView& view,
                    PixelSink* pixels, bool measure);

// What an image's picture says of its view.
DuctView image_view(Projection projection);

}  // namespace igds::duct
