#include "bccmis/io/svg.h"

#include <cstdio>

namespace bccmis::io {

std::string xml_escape(std::string_view text) {
  std::string r;
  for (const char ch : text) {
    switch (ch) {
      case '&': r += "&amp;"; break;
      case '<': r += "&lt;"; break;
      case '>': r += "&gt;"; break;
      case '"': r += "&quot;"; break;
      default: r += ch;
    }
  }
  return r;
}

std::string svg_start(double width, double height) {
  char buf[256];
  std::snprintf(buf, sizeof buf,
                "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%.0f\" height=\"%.0f\" viewBox=\"0 0 %.0f %.0f\">\n",
                width, height, width, height);
  return buf;
}

std::string svg_title(std::string_view title) {
  return "<title>" + xml_escape(title) + "</title>\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
}

std::string svg_header(double width, double height, std::string_view title) {
  return svg_start(width, height) + svg_title(title);
}

std::string svg_end() { return "</svg>\n"; }

std::string hex_colour(int red, int green, int blue) {
  char buf[8];
  std::snprintf(buf, sizeof buf, "#%02x%02x%02x", red, green, blue);
  return buf;
}

std::string text_start(double x, double baseline, std::string_view attributes) {
  char buf[128];
  std::snprintf(buf, sizeof buf, "<text x=\"%.0f\" y=\"%.0f\" ", x, baseline);
  return buf + std::string(attributes) + ">";
}

std::string circle(double cx, double cy, double radius, std::string_view attributes) {
  char buf[128];
  std::snprintf(buf, sizeof buf, "<circle cx=\"%.2f\" cy=\"%.2f\" r=\"%.2f\" ", cx, cy, radius);
  return buf + std::string(attributes) + "/>\n";
}

std::string legend_entry(double x, double baseline, std::string_view fill, std::string_view label,
                         std::string_view font) {
  char swatch[128], at[128];
  std::snprintf(swatch, sizeof swatch,
                "<rect class=\"legend\" x=\"%.0f\" y=\"%.0f\" width=\"12\" height=\"12\" fill=\"", x, baseline - 10);
  std::snprintf(at, sizeof at, "<text x=\"%.0f\" y=\"%.0f\" ", x + 16, baseline);
  return swatch + std::string(fill) + "\"/>" + at + std::string(font) + " stroke=\"none\">" + std::string(label) +
         "</text>\n";
}

}  // namespace bccmis::io
