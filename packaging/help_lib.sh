# shellcheck shell=bash
# Reads the veduta program's own --help, the one source of the man page and of the bash
# completion (make_manpage.sh, make_completion.sh), so that both list what the program has.
# Source it; the functions read CLI11's layout: a description line, "Usage: …", then sections
# ("Options:") of entries, each a name in columns 3–30 and its description from column 31
# (on the next line, indented 30, when the name is longer).

# help_text VEDUTA [SUBCOMMAND...]: `veduta SUBCOMMAND... --help`, its usage naming the program
# `veduta` whatever path it ran from (veduta diff's help comes from the veduta-diff program).
help_text() {
    local veduta=$1
    shift
    "$veduta" "$@" --help | sed -E 's/^Usage: [^ ]*veduta(-diff)? /Usage: veduta /'
}

# help_entries SECTION < HELP: the entries of SECTION (Positionals, Options, Subcommands), one
# line each: NAME, a tab, DESCRIPTION (continuation lines joined).
help_entries() {
    LC_ALL=C awk -v section="$1:" '
        function trim(s) { sub(/^ +/, "", s); sub(/ +$/, "", s); return s }
        function flush() { if (name != "") print name "\t" description; name = "" }
        BEGIN { indent = sprintf("%30s", "") }
        /^[^ ]/ { flush(); inside = ($0 == section); next }
        !inside || $0 == "" { next }
        substr($0, 1, 30) == indent {
            description = description (description == "" ? "" : " ") trim($0)
            next
        }
        {
            flush()
            if (length($0) > 30 && substr($0, 30, 1) == " ") {
                name = trim(substr($0, 3, 27)); description = trim(substr($0, 31))
            } else {
                name = trim($0); description = ""
            }
        }
        END { flush() }'
}

# help_footer < HELP: the paragraphs after the last section (veduta diff's exit codes).
help_footer() {
    LC_ALL=C awk 'NR > 2 && /^[^ ]/ && !/:$/ { print }'
}

# subcommand_names < HELP: the names of the subcommands a help text lists.
subcommand_names() { help_entries Subcommands | cut -f1; }

# command_paths VEDUTA [SUBCOMMAND...]: this command and every subcommand below it, one per
# line, as words after `veduta` (the first line empty for veduta itself).
command_paths() {
    local veduta=$1
    shift
    echo "$*"
    local sub
    for sub in $(help_text "$veduta" "$@" | subcommand_names); do command_paths "$veduta" "$@" "$sub"; done
}
