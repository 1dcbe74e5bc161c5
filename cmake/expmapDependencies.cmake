# Finds what the headers need. Shared by the build tree and the installed
# package (expmapConfig.cmake includes this file too), so a consumer resolves
# exactly the same dependencies we test against.
include(CMakeFindDependencyMacro)

set(CGAL_DO_NOT_WARN_ABOUT_CMAKE_BUILD_TYPE TRUE)
find_dependency(CGAL)
find_dependency(Eigen3 3.3 NO_MODULE)
find_dependency(CHOLMOD)
find_dependency(METIS)
# The truncated SVDs of the Poisson factor's rows below (dgesdd).
find_dependency(LAPACK)
find_dependency(Boost 1.66)
# compute_many() runs queries on std::thread.
find_dependency(Threads)
