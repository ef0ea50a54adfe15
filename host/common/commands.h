/* The subcommands of the fulgur program. Each takes the arguments after its
 * name (argv[0] is the subcommand), prints its own --help, and returns the
 * process exit code. */
#ifndef HOST_COMMON_COMMANDS_H
#define HOST_COMMON_COMMANDS_H

enum {
    CLI_OK = 0,
    CLI_RUNTIME = 1, /* the work failed: engine, I/O */
    CLI_USAGE = 2    /* bad arguments or a bad scene; the message names the cause */
};

int render_main(int argc, char **argv);
int analyze_main(int argc, char **argv);
int run_main(int argc, char **argv);
int view_main(int argc, char **argv);
int aerotex_main(int argc, char **argv); /* host/cli/aerotex.c */
int flame_main(int argc, char **argv);   /* host/cli/flame.c */

#endif
