#!/bin/sh
# The library's include folders, as compiler flags, for the scripts that
# build the library's sources outside make (the Makefile's INC is the same
# list): the public headers (include/), then the layers of src/.
echo "-Iinclude -Isrc/core -Isrc/algo -Isrc/f64"
