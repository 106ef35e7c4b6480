// main.cpp -- `rollviz` (command line + Qt GUI, headless through EGL) and `rollviz-osmesa` (command line
// only, headless through OSMesa): the same source, two link sets (see app/CMakeLists.txt).
#include "app/cli/Cli.h"

#if defined(ROLLVIZ_HAVE_GUI) && !defined(ROLLVIZ_NO_GUI)
#include "app/gui/GuiMain.h"
#endif

int main(int argc, char** argv) {
#if defined(ROLLVIZ_HAVE_GUI) && !defined(ROLLVIZ_NO_GUI)
  return rv::runCli(argc, argv, &rv::runGui);
#else
  return rv::runCli(argc, argv, {});
#endif
}
