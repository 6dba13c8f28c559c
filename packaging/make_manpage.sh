#!/usr/bin/env bash
# Writes veduta(1) from the program's own --help of every subcommand (help_lib.sh), so that the
# man page lists the options the program has. The build runs it (cmake/VedutaInstall.cmake).
# Usage: make_manpage.sh VEDUTA VERSION OUTPUT (veduta.1, or veduta.1.gz gzipped)
set -euo pipefail
veduta=${1:?usage: make_manpage.sh VEDUTA VERSION OUTPUT}
version=${2:?usage: make_manpage.sh VEDUTA VERSION OUTPUT}
output=${3:?usage: make_manpage.sh VEDUTA VERSION OUTPUT}
. "$(dirname "$0")/help_lib.sh"

# Text as roff reads it: backslashes and minus signs escaped, no line starting a request.
roff() { sed -e 's/\\/\\e/g' -e 's/-/\\-/g' -e "s/^[.']/\\\\\&&/"; }

# entries SECTION < HELP: each entry as a tagged paragraph, its name in bold.
entries() {
    local name description
    while IFS=$'\t' read -r name description; do
        printf '.TP\n.B "%s"\n%s\n' "$(roff <<<"$name")" "$(roff <<<"$description")"
    done < <(help_entries "$1")
}

# command_section WORDS...: one subcommand's description, usage, arguments, options and notes.
command_section() {
    local help
    help=$(help_text "$veduta" "$@")
    printf '.SS "veduta %s"\n' "$*"
    head -n1 <<<"$help" | roff
    printf '.PP\n'
    sed -n 's/^Usage: //p' <<<"$help" | roff
    entries Positionals <<<"$help"
    entries Options <<<"$help"
    entries Subcommands <<<"$help"
    local footer
    footer=$(help_footer <<<"$help")
    [ -z "$footer" ] || printf '.PP\n%s\n' "$(roff <<<"$footer")"
}

page() {
    local top
    top=$(help_text "$veduta")
    printf '.TH VEDUTA 1 "" "veduta %s" "User Commands"\n' "$version"
    printf '.SH NAME\nveduta \\- %s\n' "$(head -n1 <<<"$top" | sed 's/^veduta: //' | roff)"
    printf '.SH SYNOPSIS\n.B veduta\n.RI [ OPTIONS ] " " SUBCOMMAND " " ...\n'
    printf '.SH DESCRIPTION\n'
    printf 'Each subcommand has its options; \\fBveduta \\fISUBCOMMAND \\fB\\-\\-help\\fR prints them.\n'
    printf '.SH OPTIONS\n'
    entries Options <<<"$top"
    printf '.SH COMMANDS\n'
    local words
    while IFS= read -r words; do
        # shellcheck disable=SC2086 # the words of a command path
        [ -z "$words" ] || command_section $words
    done < <(command_paths "$veduta")
    cat <<'ROFF'
.SH EXIT STATUS
0 done; 1 bad input (a scene or data file is wrong, the message says where); 2 bad command
line; 3 an output could not be written, or an internal error.
\fBveduta diff\fR: 0 the images agree, 1 they differ, 2 an error.
.SH ENVIRONMENT
.TP
.B VEDUTA_IMAGE_PLUGIN
The image plugin to load instead of \fIveduta\-images.so\fR.
.TP
.B VEDUTA_CACHE_DIR
The texture cache (else \fI$XDG_CACHE_HOME/veduta/textures\fR, else \fI~/.cache/veduta/textures\fR).
.TP
.B OCIO
The OpenColorIO config of display images (else veduta's own).
.SH FILES
.TP
.I ../lib/veduta/
beside the program's folder (\fI/usr/lib/veduta/\fR): the image plugin \fIveduta\-images.so\fR and
the \fIveduta\-diff\fR program.
.TP
.I ../share/veduta/
(\fI/usr/share/veduta/\fR): the shipped rules, materials, environments, example scenes, cities and
data.
.SH SEE ALSO
The documentation in \fI/usr/share/doc/veduta/\fR.
ROFF
}

# Gzipped for an OUTPUT.gz, as Debian installs man pages (-n: no name or time inside, so the
# same help gives the same bytes).
case $output in
*.gz) page | gzip -9n >"$output.tmp" ;;
*) page >"$output.tmp" ;;
esac
mv "$output.tmp" "$output"
