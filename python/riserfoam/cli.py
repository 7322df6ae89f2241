"""The command-line convention of the project's scripts: -h, -help or
--help prints the script's documentation (its usage first) and exits 0,
before anything else is read or imported (a pvbatch script's ParaView
included)."""
import sys

HELP = ("-h", "-help", "--help")


def help_requested(doc, argv=None):
    """Print doc and exit 0 when the command line asks for help."""
    if any(a in HELP for a in (sys.argv[1:] if argv is None else argv)):
        print(doc.strip())
        sys.exit(0)
