// A module whose stamp says it was built for rollviz 0.0.0 with another compiler: refused before its entry
// point runs (the entry point would register a problem, which must then not appear).
#include "scenes/Module.h"

#undef ROLLVIZ_ABI_STAMP
#define ROLLVIZ_ABI_STAMP "rollviz 0.0.0; gcc 1; libstdc++ cxx11 abi 0; C++ 201103"

ROLLVIZ_MODULE(registrar) {
  throw std::runtime_error("the entry point of a module with a wrong stamp ran");
  (void)registrar;
}
