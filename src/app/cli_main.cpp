#include "app/cli.h"

#include <iostream>
#include <string>
#include <vector>

#include <unistd.h>

int main(int argc, char** argv)
{
    std::vector<std::string> args;
    for (int i = 1; i < argc; ++i)
        args.emplace_back(argv[i]);
    return impetus::app::runCli(args, std::cout, std::cerr, isatty(STDERR_FILENO) != 0);
}
