// fuzz_stuff: the whole `bccmis stuff` path on a small triangle-mesh text
// (spec/stuffing.md S21-S26): the reader (OFF, OBJ or STL), the soup's shape
// or, with the strict bit, the clean mesh's, then mesh_shape() with the
// checker's stuffed-mesh layer at level 0-2.
//
// Input: byte 0 the options (bits 0-1: the level, 0-2; bits 2-4: --cells
// 3-10; bit 5: strict), byte 1 the format (0 OFF, 1 OBJ, 2 STL, by value mod
// 3), then the file's text.
//
// The documented refusals (io::ReadError, ShapeError: bad input, exit 2) and
// S27's warnings turned errors by the check are fine; any other CheckError
// (the mesh fails the checker's stuffed-mesh layer), any other exception, a
// crash or a sanitizer report is a finding.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>

#include "bccmis/io/obj.h"
#include "bccmis/io/off.h"
#include "bccmis/io/read_error.h"
#include "bccmis/io/stl.h"
#include "bccmis/stuff/mesh_shape.h"
#include "bccmis/stuff/surface.h"

namespace {

using namespace bccmis;

[[noreturn]] void finding(const char* what, const std::string& why) {
  std::fprintf(stderr, "fuzz_stuff: %s: %s\n", what, why.c_str());
  std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 2) return 0;
  const std::uint8_t options = data[0];
  const int format = data[1] % 3;
  const std::string text(reinterpret_cast<const char*>(data + 2), size - 2);
  stuff::Settings settings;
  settings.lattice.max_level = (options & 3) % 3;
  settings.lattice.cells = 3 + ((options >> 2) & 7);
  settings.check = true;
  settings.memory_limit = 256e6;  // S25: small runs only
  const bool strict = (options >> 5) & 1;
  try {
    const io::TriangleSoup soup = format == 0   ? io::read_off("fuzz.off", text)
                                  : format == 1 ? io::read_obj("fuzz.obj", text)
                                                : io::read_stl("fuzz.stl", text);
    const auto shape = strict ? stuff::make_mesh_shape(soup.vertices, soup.triangles, "fuzz")
                              : stuff::make_soup_shape(soup.vertices, soup.triangles, "fuzz");
    const stuff::Meshed m = stuff::mesh_shape(*shape, settings);
    if (m.stuffed.mesh.tets.empty()) finding("an empty mesh returned", "S26 refuses it");
  } catch (const io::ReadError&) {
  } catch (const stuff::ShapeError&) {
  } catch (const stuff::CheckError& e) {
    // S27's warnings (a changed topology) are errors under --check, as
    // documented; the checker's own layer failing is a finding.
    if (std::string(e.what()).find(": the mesh's boundary has ") == std::string::npos) finding("the checker", e.what());
  } catch (const std::exception& e) {
    finding("an exception", e.what());
  }
  return 0;
}
