#include "cfd/linear/hypre_library.hpp"

#include <string>

#include "cfd/base/internal_error.hpp"

namespace parcelflow::cfd {

void initialiseHypreOnce() {
  static const bool initialised = [] {
    PARCELFLOW_HYPRE_CALL(HYPRE_Init());
    return true;
  }();
  (void)initialised;
}

void checkHypre(HYPRE_Int code, const char* call, const char* file, int line) {
  if (code == 0) return;
  // HYPRE_DescribeError leaves the text alone for codes outside its categories, and reads the
  // failing argument's number from the global flag: describe before clearing.
  char description[256] = "[unknown error] ";
  HYPRE_DescribeError(code, description);
  HYPRE_ClearAllErrors();
  throw InternalError("internal error: hypre call " + std::string(call) + " failed with code " +
                      std::to_string(code) + " " + description + "at " + file + ":" +
                      std::to_string(line));
}

}  // namespace parcelflow::cfd
