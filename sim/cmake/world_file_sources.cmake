# include(): WORLD_FILE_SOURCES, the world file's reader (world.json:
# sim/src/world/world_file.cpp and the pieces world_file_reader.hpp lists),
# as absolute paths, so the simulator, tests/world and tests/fuzz (a
# project of its own) compile the same list. Each also needs
# sim/src/world/world_random.c and cli/src/suggest.cpp.
set(WORLD_FILE_SOURCES)
foreach(piece world_file world_json_text world_file_checks world_file_geometry world_file_arena world_file_robots world_file_limits world_file_eeprom world_file_epuck)
  list(APPEND WORLD_FILE_SOURCES ${CMAKE_CURRENT_LIST_DIR}/../src/world/${piece}.cpp)
endforeach()
