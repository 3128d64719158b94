namespace URWPGSim2D.Server.Cli.Syntax;

/// <summary>
/// The shell scripts of <c>completion</c>: each hands the command line up to the cursor to
/// <c>urwpgsim2d "[suggest]" LINE</c> (<see cref="ShellCompletion"/>; the cursor is at the line's
/// end, so no position is needed whatever the shell counts in) and offers the answer;
/// when the program offers nothing, the shell completes file names as usual.
/// </summary>
internal static class CompletionScripts
{
    /// <summary>For bash (<c>~/.bashrc</c>). Bash splits words at <c>=</c> and <c>:</c>; the script gives back only the part after them.</summary>
    public const string Bash = """
        # urwpgsim2d tab completion for bash: urwpgsim2d completion bash >> ~/.bashrc
        _urwpgsim2d_complete()
        {
            local line="${COMP_LINE:0:COMP_POINT}"
            local cur="${COMP_WORDS[COMP_CWORD]}"
            local word="${line##*[[:space:]]}"
            local prefix="${word:0:${#word}-${#cur}}"
            local IFS=$'\n' f
            local -a found
            found=($(urwpgsim2d "[suggest]" "$line" 2>/dev/null))
            COMPREPLY=()
            for f in "${found[@]}"; do
                [[ "$f" == "$prefix"* ]] && COMPREPLY+=("${f:${#prefix}}")
            done
            if [[ ${#COMPREPLY[@]} -eq 1 && "${COMPREPLY[0]}" == */ ]]; then
                compopt -o nospace 2>/dev/null
            fi
        }
        complete -o default -F _urwpgsim2d_complete urwpgsim2d

        """;

    /// <summary>For zsh (<c>~/.zshrc</c>, after <c>compinit</c>).</summary>
    public const string Zsh = """
        # urwpgsim2d tab completion for zsh: urwpgsim2d completion zsh >> ~/.zshrc
        _urwpgsim2d() {
            local line="${BUFFER[1,CURSOR]}"
            local -a found
            found=("${(@f)$(urwpgsim2d "[suggest]" "$line" 2>/dev/null)}")
            found=(${found:#})
            if (( ${#found} )); then
                compadd -Q -- "${found[@]}"
            else
                _files
            fi
        }
        (( $+functions[compdef] )) || { autoload -Uz compinit && compinit }
        compdef _urwpgsim2d urwpgsim2d

        """;

    /// <summary>For PowerShell (<c>$PROFILE</c>).</summary>
    public const string PowerShell = """
        # urwpgsim2d tab completion for PowerShell: urwpgsim2d completion pwsh >> $PROFILE
        Register-ArgumentCompleter -Native -CommandName urwpgsim2d -ScriptBlock {
            param($wordToComplete, $commandAst, $cursorPosition)
            $line = $commandAst.ToString()
            $upTo = $cursorPosition - $commandAst.Extent.StartOffset
            $line = if ($upTo -lt $line.Length) { $line.Substring(0, $upTo) } else { $line.PadRight($upTo) }
            urwpgsim2d "[suggest]" "$line" 2>$null | ForEach-Object {
                [System.Management.Automation.CompletionResult]::new($_, $_, 'ParameterValue', $_)
            }
        }

        """;
}
