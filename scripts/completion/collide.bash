# bash completion for collide (installed as share/bash-completion/completions/collide).
_collide() {
    local cur prev words cword
    _init_completion || return
    local commands="render thumbnail check scenes simulate pq heap puzzle bench compare"
    if [[ $cword -eq 1 ]]; then
        COMPREPLY=($(compgen -W "$commands --help --version" -- "$cur"))
        return
    fi
    local command=${words[1]}
    case $prev in
        -o|--output|--layout-json|--export|--events-log|--font|--dump-rgba|--diff)
            _filedir
            return ;;
        --mode) COMPREPLY=($(compgen -W "both event time" -- "$cur")); return ;;
        -q|--quality) COMPREPLY=($(compgen -W "l m h k" -- "$cur")); return ;;
        --engine)
            if [[ $command == simulate ]]; then
                COMPREPLY=($(compgen -W "fast classic time" -- "$cur"))
            else
                COMPREPLY=($(compgen -W "fast classic" -- "$cur"))
            fi
            return ;;
        --pq) COMPREPLY=($(compgen -W "unordered ordered binary dary:4 indexed" -- "$cur")); return ;;
        --td-detect) COMPREPLY=($(compgen -W "all-pairs grid" -- "$cur")); return ;;
        --camera) COMPREPLY=($(compgen -W "fixed orbit" -- "$cur")); return ;;
        --projection) COMPREPLY=($(compgen -W "ortho perspective" -- "$cur")); return ;;
        --color) COMPREPLY=($(compgen -W "scene speed mass tag" -- "$cur")); return ;;
        --overlays) COMPREPLY=($(compgen -W "lesson full none" -- "$cur")); return ;;
        --theme) COMPREPLY=($(compgen -W "dark light" -- "$cur")); return ;;
        --format)
            if [[ $command == pq ]]; then
                COMPREPLY=($(compgen -W "text csv markdown" -- "$cur"))
            else
                COMPREPLY=($(compgen -W "mp4 gif png" -- "$cur"))
            fi
            return ;;
        --gl) COMPREPLY=($(compgen -W "auto osmesa egl egl-device glfw" -- "$cur")); return ;;
        --progress) COMPREPLY=($(compgen -W "auto bar json none" -- "$cur")); return ;;
    esac
    if [[ $cur == -* ]]; then
        # The options of the command, as its own --help lists them.
        local options
        options=$("${words[0]}" "$command" --help 2>/dev/null |
                  grep -oE '(^|[ ,])--?[a-zA-Z][-a-zA-Z]*' | tr -d ' ,' | sort -u)
        COMPREPLY=($(compgen -W "$options" -- "$cur"))
        return
    fi
    case $command in
        render|thumbnail|check|simulate)
            # Built-in scene names, and scene files.
            local scenes
            scenes=$("${words[0]}" scenes 2>/dev/null | awk '{print $1}')
            COMPREPLY=($(compgen -W "$scenes" -- "$cur"))
            _filedir '@(toml|txt)'
            ;;
    esac
}
complete -F _collide collide
