# Sourced by run_gui.sh and run_gui_fresh.sh: a fresh profile for the ParaView GUI. HOME and the
# XDG folders point to a new temporary folder ($tmp, removed on exit), so that no setting, no
# recent file and no Python of the user's can interfere.
tmp=$(mktemp -d "${TMPDIR:-/tmp}/stylize-gui.XXXXXX") || exit 1
trap 'rm -rf "$tmp"' EXIT
mkdir -p "$tmp/home" "$tmp/config" "$tmp/cache" "$tmp/data" "$tmp/runtime"
chmod 700 "$tmp/runtime"
HOME="$tmp/home" XDG_CONFIG_HOME="$tmp/config" XDG_CACHE_HOME="$tmp/cache"
XDG_DATA_HOME="$tmp/data" XDG_RUNTIME_DIR="$tmp/runtime"
export HOME XDG_CONFIG_HOME XDG_CACHE_HOME XDG_DATA_HOME XDG_RUNTIME_DIR
