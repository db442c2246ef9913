# bash completion for collide: subcommands, their options, the values an option accepts, and
# lesson ids. Installed as share/bash-completion/completions/collide (bash-completion loads it
# the first time `collide` is completed); without bash-completion: source this file.
#
# Everything is asked of the program being completed, so it always matches its version:
# the subcommands from `collide --help`, a subcommand's options (and whether each takes a
# value, and the values of a {a,b,c} choice) from `collide SUBCOMMAND --help`, the lesson ids
# from `collide lessons`.

# The options of `collide SUBCOMMAND --help`, one a line: "NAME TYPE CHOICES" (TYPE empty for a
# flag; CHOICES the comma-separated values of a {...} list, or empty).
_collide_options() {
    "$1" "$2" --help 2>/dev/null | sed -nE \
        's/^ +(-[A-Za-z],)?(--[a-z][a-z0-9-]*)( ([A-Z]+)(:\{([^}]*)\})?([ =]|$))?.*/\1 \2 \4 \6/p' |
        while read -r first second rest; do
            if [[ $first == -?, ]]; then  # "-o, --output TEXT": a line for each name
                printf '%s %s\n' "${first%,}" "$rest" "$second" "$rest"
            else
                printf '%s %s %s\n' "$first" "$second" "$rest"
            fi
        done
}

_collide() {
    local cur=${COMP_WORDS[COMP_CWORD]} prev=${COMP_WORDS[COMP_CWORD - 1]}
    local prog=${COMP_WORDS[0]} sub="" i
    COMPREPLY=()
    for ((i = 1; i < COMP_CWORD; i++)); do
        [[ ${COMP_WORDS[i]} != -* ]] && { sub=${COMP_WORDS[i]}; break; }
    done

    if [[ -z $sub ]]; then
        local subcommands
        subcommands=$("$prog" --help 2>/dev/null | sed -n '/^Subcommands:/,$ s/^  \([a-z][a-z-]*\) .*/\1/p')
        COMPREPLY=($(compgen -W "$subcommands -h --help --version" -- "$cur"))
        return
    fi

    local options name type choices
    options=$(_collide_options "$prog" "$sub")
    # The value of an option: its {choices}, a directory for -o, sizes for --size.
    while read -r name type choices; do
        [[ $name == "$prev" && -n $type ]] || continue
        if [[ -n $choices ]]; then
            COMPREPLY=($(compgen -W "${choices//,/ }" -- "$cur"))
        elif [[ $name == -o || $name == --output ]]; then
            COMPREPLY=($(compgen -d -- "$cur"))
        elif [[ $name == --size ]]; then
            COMPREPLY=($(compgen -W "480p 720p 1080p 1440p" -- "$cur"))
        elif [[ $type == TEXT ]]; then
            COMPREPLY=($(compgen -f -- "$cur"))
        fi
        return
    done <<<"$options"

    if [[ $cur == -* ]]; then
        COMPREPLY=($(compgen -W "$(cut -d' ' -f1 <<<"$options")" -- "$cur"))
        return
    fi
    # A positional argument: files, and for the commands that take one, lesson ids.
    case $sub in
        step | render | material | worksheet | gui | compare)
            local ids
            ids=$("$prog" lessons 2>/dev/null | awk 'NR > 1 { print $2 }')
            COMPREPLY=($(compgen -W "$ids" -- "$cur") $(compgen -f -- "$cur"))
            ;;
        solve)
            COMPREPLY=($(compgen -f -- "$cur"))
            ;;
    esac
}
complete -o filenames -F _collide collide
