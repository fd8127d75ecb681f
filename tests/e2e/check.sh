# Sourced by e2e scripts: check DESCRIPTION EXPECTED_STATUS REGEX COMMAND...
# runs COMMAND and counts it in passed or failed: its exit status must be
# EXPECTED_STATUS and its output (standard output and error) match REGEX
# (grep -E, across lines); a failure prints what came instead.
passed=0 failed=0
check() {
    local what=$1 status=$2 regex=$3
    shift 3
    local out
    out=$("$@" 2>&1)
    local got=$?
    if [ "$got" -eq "$status" ] && printf '%s' "$out" | grep -Ezq -- "$regex"; then
        passed=$((passed + 1))
    else
        failed=$((failed + 1))
        echo "FAILED: $what: exit $got (expected $status):"
        printf '%s\n' "$out"
    fi
}

# expect STATUS REGEX COMMAND...: runs COMMAND and counts it likewise; its
# exit status must be STATUS and its standard error match REGEX (grep -E,
# line by line); standard output is not looked at.
expect() {
    local status=$1 regex=$2
    shift 2
    local err
    err=$("$@" 2>&1 >/dev/null)
    local got=$?
    if [ "$got" -eq "$status" ] && printf '%s' "$err" | grep -Eq -- "$regex"; then
        passed=$((passed + 1))
    else
        failed=$((failed + 1))
        echo "FAILED: $* -> exit $got (expected $status), stderr:"
        printf '%s\n' "$err"
    fi
}

# fail WHAT [FILE...]: stops the script with "FAILED: WHAT" and each FILE's
# contents, to see why.
fail() { echo "FAILED: $1"; shift; for f in "$@"; do echo "--- $f"; cat "$f"; done; exit 1; }

# logged STATUS REGEX COMMAND...: runs COMMAND into out.log (shown) and
# stops the script unless its exit status is STATUS and a line of its
# output (standard output and error) matches REGEX (grep -E); out.log
# stays for further greps.
logged() {
    local want=$1 regex=$2 status=0
    shift 2
    "$@" > out.log 2>&1 || status=$?
    cat out.log
    [ "$status" = "$want" ] || fail "$* exited $status, not $want"
    grep -Eq -- "$regex" out.log || fail "$*: no line matches $regex"
}
