# Triangle soups by their generalized winding number (spec/stuffing.md
# S17-S19, src/bccmis/soup/): the solid angle against known values, closed
# and open meshes, the far-field bound against the exact sum, and the side
# of points on the triangles.
bccmis_add_gtest(soup_tests SOURCES winding_number_test.cpp LIBS bccmis::soup LABELS unit)
