# The unilateral sources the external drivers' yardstick compiles (our LCP
# reader and KKT residuals, without the core library: see CMakeLists.txt
# here), kept in one list for this folder's build and for the test that
# links them alone (tests/external), so that a source which comes to need
# another fails in the test suite rather than in the next benchmark run.
# Needs UNILATERAL_SOURCE_DIR, the repository's root.
set(LCP_YARDSTICK_SOURCES
  ${UNILATERAL_SOURCE_DIR}/source/base/output_file.cc
  ${UNILATERAL_SOURCE_DIR}/source/base/text.cc
  ${UNILATERAL_SOURCE_DIR}/source/lcp/io.cc
  ${UNILATERAL_SOURCE_DIR}/source/lcp/problem.cc)
