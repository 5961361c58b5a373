# The Python twin of Filters/ArrayNames.h: shapesplines_python_array_names(HEADER OUTPUT)
# writes OUTPUT, a module with one constant per name of the header's namespace
# shapesplines::names (a tuple for a std::array of names), so that Python code
# and the tests read the strings the filters write instead of spelling them again.
function(shapesplines_python_array_names header output)
  file(READ "${header}" text)
  # Comments could hold anything that looks like a declaration; a semicolon
  # would split CMake's lists.
  string(REGEX REPLACE "//[^\n]*" "" text "${text}")
  string(REPLACE ";" "\n" text "${text}")
  string(CONCAT module "\"\"\"The names of the arrays the ShapeSplines filters write.\n\n"
    "Generated from Filters/ArrayNames.h (shapesplines::names) when the project is\n"
    "configured: edit the header, not this file.\n\"\"\"\n")
  string(REGEX MATCHALL "constexpr const char\\* [A-Za-z0-9_]+ = \"[^\"]*\"" scalars "${text}")
  foreach (declaration IN LISTS scalars)
    string(REGEX REPLACE "^constexpr const char\\* ([A-Za-z0-9_]+) = (\"[^\"]*\")$" "\\1 = \\2"
      assignment "${declaration}")
    string(APPEND module "${assignment}\n")
  endforeach ()
  string(REGEX MATCHALL "constexpr std::array<const char\\*, [0-9]+> [A-Za-z0-9_]+ = {[^}]*}" lists
    "${text}")
  foreach (declaration IN LISTS lists)
    string(REGEX REPLACE "^constexpr std::array<const char\\*, [0-9]+> ([A-Za-z0-9_]+) = {([^}]*)}$"
      "\\1" name "${declaration}")
    string(REGEX REPLACE "^[^{]*{([^}]*)}$" "\\1" values "${declaration}")
    string(REGEX REPLACE "[ \t\n]+" " " values "${values}")
    string(STRIP "${values}" values)
    string(APPEND module "${name} = (${values})\n")
  endforeach ()
  list(LENGTH scalars scalar_count)
  if (scalar_count EQUAL 0)
    message(FATAL_ERROR "no array names found in ${header}")
  endif ()
  # Written only when it changes, and read again when the header changes.
  file(CONFIGURE OUTPUT "${output}" CONTENT "${module}" @ONLY)
  set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS "${header}")
endfunction()
