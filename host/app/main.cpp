#include "cli.h"

int main(int argc, char** argv) {
  return rtvk::run_cli(argc, argv);
}
