# GMP with its C++ classes (gmpxx), the exact oracle of the test checkers: defines GMP_FOUND
# and the imported target GMP::gmpxx. CMAKE_DISABLE_FIND_PACKAGE_GMP=ON hides it (to try a
# build without it).
find_path(GMP_INCLUDE_DIR gmpxx.h)
find_library(GMPXX_LIBRARY gmpxx)
find_library(GMP_LIBRARY gmp)
include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(GMP REQUIRED_VARS GMP_INCLUDE_DIR GMPXX_LIBRARY GMP_LIBRARY)
mark_as_advanced(GMP_INCLUDE_DIR GMPXX_LIBRARY GMP_LIBRARY)
if(GMP_FOUND AND NOT TARGET GMP::gmpxx)
  add_library(GMP::gmpxx INTERFACE IMPORTED)
  set_target_properties(GMP::gmpxx PROPERTIES
    INTERFACE_INCLUDE_DIRECTORIES "${GMP_INCLUDE_DIR}"
    INTERFACE_LINK_LIBRARIES "${GMPXX_LIBRARY};${GMP_LIBRARY}")
endif()
