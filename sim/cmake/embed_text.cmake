# cmake -DINPUT=file -DOUTPUT=file.c -DNAME=symbol -P embed_text.cmake:
# the file as a C char array (zero-terminated), so the simulator carries it.
file(READ "${INPUT}" hex HEX)
string(REGEX REPLACE "([0-9a-f][0-9a-f])" "0x\\1," bytes "${hex}")
string(REGEX REPLACE "((0x..,){24})" "\\1\n" bytes "${bytes}")
get_filename_component(name "${INPUT}" NAME)
file(WRITE "${OUTPUT}" "/* Generated from ${name} by sim/cmake/embed_text.cmake: do not edit. */\n"
  "const char ${NAME}[] = {\n${bytes}0};\n")
