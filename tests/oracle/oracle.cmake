# Included by tests/CMakeLists.txt: the oracle utilities' tests
# (src/bccmis/oracle); the 2D picture is checked through the CLI (tests/cli).
# The 3D picture of bccmis render (src/bccmis/oracle d3::render_svg): the leaves
# a slice cuts, by hand and as a tiling of every plane; hand counts.
bccmis_add_gtest(d3_render_tests SOURCES d3/render_test.cpp LIBS bccmis::oracle bccmis::d3 DEFINITIONS BCCMIS_SPEC_EXAMPLES_DIR="${PROJECT_SOURCE_DIR}/spec/examples" LABELS unit)
