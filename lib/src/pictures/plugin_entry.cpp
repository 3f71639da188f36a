// arnoldweb: the pictures' plugin's one exported entry point: the table of
// what it draws, checked by the library that opens it (output/picture_plugin.cpp).
#include "arnoldweb/version.hpp"
#include "output/picture_plugin.hpp"
#include "pictures/drawing.hpp"
#include "pictures/picture_table.hpp"

extern "C" __attribute__((visibility("default"))) const arnoldweb::detail::PictureFunctions*
arnoldweb_picture_functions() {
  using namespace arnoldweb::detail;
  static const PictureFunctions functions{ARNOLDWEB_VERSION,
                                          sizeof(PictureFunctions),
                                          draw_sphere_png,
                                          draw_mollweide_png,
                                          render_zoom_png,
                                          draw_figure_png,
                                          write_output_pictures,
                                          [](const std::string& name) { return find_picture(name) != nullptr; }};
  return &functions;
}
