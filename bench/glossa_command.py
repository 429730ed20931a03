"""The command line of one `glossa run` for the bench scripts: the deck, an output directory,
`--set` overrides, and mpiexec (with the flags this machine needs) on more than one rank."""


def glossa_run_command(glossa, deck, out, overrides=(), ranks=1):
    cmd = [glossa, "run", deck, "--output", out, "--quiet"]
    for o in overrides:
        cmd += ["--set", o]
    if ranks > 1:
        cmd = ["mpiexec", "--allow-run-as-root", "--oversubscribe", "-np", str(ranks)] + cmd
    return cmd
