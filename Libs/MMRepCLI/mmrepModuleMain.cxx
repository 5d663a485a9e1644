// Executable wrapper of a CLI module: the science lives in the module's shared library (Slicer loads it too).
extern "C" int ModuleEntryPoint(int argc, char* argv[]);

int main(int argc, char* argv[]) { return ModuleEntryPoint(argc, argv); }
