// bccmis::io: the pieces every SVG picture of bccmis is made of (the 2D and
// 3D lattice pictures of `bccmis render`, the stuffed-mesh view and the
// angle histogram): escaping, the document's start and end, colours, text
// and legend entries, circles. Coordinates are written rounded to whole pixels,
// a circle's to hundredths.
#pragma once

#include <string>
#include <string_view>

namespace bccmis::io {

/// `text` with `&`, `<`, `>` and `"` as XML entities.
std::string xml_escape(std::string_view text);

/// The <svg> start tag of a width x height picture (viewBox from 0 0), and a newline.
std::string svg_start(double width, double height);
/// The document's <title> (escaped) and a white background, a line each.
std::string svg_title(std::string_view title);
/// svg_start, then svg_title: how every picture opens.
std::string svg_header(double width, double height, std::string_view title);
/// The </svg> end tag and a newline.
std::string svg_end();

/// `#rrggbb` of channels in [0, 255].
std::string hex_colour(int red, int green, int blue);

/// The start tag <text x=".." y=".." ATTRIBUTES> (no newline).
std::string text_start(double x, double baseline, std::string_view attributes);

/// A circle on one line: <circle cx=".." cy=".." r=".." ATTRIBUTES/> with
/// the centre and radius to hundredths of a pixel (%.2f).
std::string circle(double cx, double cy, double radius, std::string_view attributes);

/// A legend entry on one line: a 12 x 12 swatch of `fill` at x whose bottom
/// is 2 below `baseline`, and `label` (not escaped) 16 to its right, in `font`.
std::string legend_entry(double x, double baseline, std::string_view fill, std::string_view label,
                         std::string_view font);

}  // namespace bccmis::io
