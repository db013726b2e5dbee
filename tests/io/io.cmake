# The readers and writers of bccmis::io (src/bccmis/io/), format by format.
find_package(ZLIB REQUIRED)
bccmis_add_gtest(io_tests SOURCES base64_test.cpp ply_read_test.cpp regions_test.cpp pvd_test.cpp surface_format_test.cpp vtu_compressed_test.cpp
                 LIBS bccmis::io ZLIB::ZLIB LABELS unit)
# D18's staging directory (tools/bccmis/staging_directory.h): a lock it
# cannot take is a warning naming the directory and the reason.
bccmis_add_gtest(staging_directory_tests SOURCES staging_directory_test.cpp LIBS bccmis::cli_stuff LABELS unit)

# The FEM files used as FEM codes use them (spec/mesh3d.md M20-M23): gmsh
# lists the .msh's physical groups, meshio reads every format in ASCII and
# binary alike (tests/io/fem_files_test.py); and P1 Poisson problems
# assembled in numpy from the .msh, Dirichlet data on its boundary group,
# match the exact solutions (tests/io/fem_poisson_test.py).
bccmis_add_test(cli.fem_files COMMAND ${BCCMIS_SYSTEM_PYTHON3} ${CMAKE_CURRENT_LIST_DIR}/fem_files_test.py
                                    $<TARGET_FILE:bccmis> ${PROJECT_SOURCE_DIR}/spec/examples/d3/face_refined.state
                                    LABELS cli TIMEOUT 120)
bccmis_add_test(cli.fem_poisson COMMAND ${BCCMIS_SYSTEM_PYTHON3} ${CMAKE_CURRENT_LIST_DIR}/fem_poisson_test.py
                                      $<TARGET_FILE:bccmis>
                                      LABELS cli TIMEOUT 120)

# Outputs fail early and leave nothing (spec/cli.md, "Outputs"): an
# unwritable -o ends `stuff` before meshing with the reason; SIGTERM and
# SIGINT while meshing leave no temporary and no output; --animate makes each
# frame's temporary as it writes the frame (tests/io/outputs_early_test.py).
bccmis_add_test(cli.outputs_early COMMAND ${BCCMIS_SYSTEM_PYTHON3} ${CMAKE_CURRENT_LIST_DIR}/outputs_early_test.py
                                        $<TARGET_FILE:bccmis>
                                        LABELS cli TIMEOUT 120)

# bccmis render reads the .vtu and .msh that stuff and mesh write, besides
# the .mesh (tests/io/render_readers_test.py).
bccmis_add_test(cli.render_readers COMMAND ${BCCMIS_SYSTEM_PYTHON3} ${CMAKE_CURRENT_LIST_DIR}/render_readers_test.py
                                         $<TARGET_FILE:bccmis>
                                         LABELS cli TIMEOUT 120)
