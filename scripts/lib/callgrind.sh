# Shared by the instruction-count scripts: installs valgrind (Debian's package) when missing and
# defines `instructions BIN ARGS...`, the instructions callgrind counts for one run of BIN.
if ! command -v valgrind >/dev/null; then
    echo "installing valgrind (Debian package)" >&2
    if [ "$(id -u)" = 0 ]; then apt-get update -qq && apt-get install -y -qq valgrind >/dev/null
    else sudo apt-get update -qq && sudo apt-get install -y -qq valgrind >/dev/null; fi
fi
instructions() {
    local out
    out=$(mktemp)
    valgrind --tool=callgrind --callgrind-out-file="$out" "$@" >/dev/null 2>&1
    awk '/^summary:/ {print $2}' "$out"
    rm -f "$out"
}
