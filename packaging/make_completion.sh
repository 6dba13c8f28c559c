#!/usr/bin/env bash
# Writes veduta's bash completion from the program's own --help of every subcommand
# (help_lib.sh): the subcommands, each one's options, and the values of options that take one
# of a list. Written when the program is built rather than read from --help at each Tab, which
# would start veduta (and for `diff`, OpenImageIO) every time. The build runs it
# (cmake/VedutaInstall.cmake).
# Usage: make_completion.sh VEDUTA OUTPUT
set -euo pipefail
veduta=${1:?usage: make_completion.sh VEDUTA OUTPUT}
output=${2:?usage: make_completion.sh VEDUTA OUTPUT}
. "$(dirname "$0")/help_lib.sh"

# option_words < ENTRIES: the option names of help_entries' lines (-o,--output TEXT → -o --output).
option_words() { cut -f1 | cut -d' ' -f1 | tr ',' '\n' | grep '^-' | tr '\n' ' ' | sed 's/ $//'; }

# choice_lines KEY < ENTRIES: `["KEY --option"]="a b c"` for each option of a {a,b,c} list.
choice_lines() {
    local name option choices
    while IFS=$'\t' read -r name _; do
        [[ $name =~ \{([^}]*)\} ]] || continue
        choices=$(sed -E 's/->[^,]*//g; s/,/ /g' <<<"${BASH_REMATCH[1]}")  # CLI11 maps: shaded->0
        for option in $(option_words <<<"$name"); do printf '    ["%s %s"]="%s"\n' "$1" "$option" "$choices"; done
    done
}

tables() {
    local words key help subcommands=() options=() choices=()
    while IFS= read -r words; do
        # shellcheck disable=SC2086 # the words of a command path
        help=$(help_text "$veduta" $words)
        key="veduta${words:+ $words}"
        subcommands+=("    [\"$key\"]=\"$(subcommand_names <<<"$help" | tr '\n' ' ' | sed 's/ $//')\"")
        options+=("    [\"$key\"]=\"$(help_entries Options <<<"$help" | option_words)\"")
        mapfile -t -O ${#choices[@]} choices < <(help_entries Options <<<"$help" | choice_lines "$key")
    done < <(command_paths "$veduta")
    printf 'declare -gA _veduta_subcommands=(\n%s\n)\n' "$(printf '%s\n' "${subcommands[@]}")"
    printf 'declare -gA _veduta_options=(\n%s\n)\n' "$(printf '%s\n' "${options[@]}")"
    printf 'declare -gA _veduta_choices=(\n%s\n)\n' "$(printf '%s\n' "${choices[@]}")"
}

{
    echo "# bash completion for veduta, written from its --help by packaging/make_completion.sh."
    echo "# Keys are command paths (\"veduta atkis info\"); declared global (-g) because"
    echo "# bash-completion sources this file inside a function."
    tables
    cat <<'BASH'

# The command path is the subcommand words before the cursor; after an option with a list of
# values those values, after a dash the path's options, else its subcommands, and where it has
# none, files (-o default).
_veduta() {
    local cur=${COMP_WORDS[COMP_CWORD]} prev=${COMP_WORDS[COMP_CWORD - 1]} command=veduta word i
    for ((i = 1; i < COMP_CWORD; i++)); do
        word=${COMP_WORDS[i]}
        [[ " ${_veduta_subcommands[$command]} " == *" $word "* ]] && command+=" $word"
    done
    local words=${_veduta_choices["$command $prev"]-}
    if [[ -z $words ]]; then
        if [[ $cur == -* ]]; then words=${_veduta_options[$command]}; else words=${_veduta_subcommands[$command]}; fi
    fi
    mapfile -t COMPREPLY < <(compgen -W "$words" -- "$cur")
}
complete -o bashdefault -o default -F _veduta veduta
BASH
} >"$output.tmp"
mv "$output.tmp" "$output"
