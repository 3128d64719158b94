using System;
using System.Collections.Generic;
using System.CommandLine;
using URWPGSim2D.Server.Cli.Syntax;

namespace URWPGSim2D.Server.Cli;

/// <summary>
/// <c>query FILE</c>: reads <c>{"shapes": [SHAPE…], "queries": [QUERY…]}</c> and writes one JSON
/// line per query (<see cref="QueryAnswers"/>). The whole input is validated before anything is
/// computed or written: on bad input stdout stays empty.
/// </summary>
internal sealed class QueryCommand : ICliCommand
{
    /// <inheritdoc />
    public string Name => "query";

    /// <inheritdoc />
    public string Synopsis => "query FILE";

    /// <inheritdoc />
    public string Summary => "Distances, ray casts, shape casts and box overlaps over shapes from a JSON file.";

    private static readonly Option<bool> HelpOption = CliSyntax.Help();

    /// <inheritdoc />
    public Command Syntax { get; } = CliSyntax.Command("query", "shapes and queries (JSON), - for stdin", FileArgument.Declare("shapes and queries (JSON), - for stdin"), HelpOption);

    private string Usage => $"{CliApp.ProgramName} {Synopsis}";

    /// <inheritdoc />
    public int Run(IReadOnlyList<CommandLineWord> words, CliConsole console)
    {
        if (words.Count == 1 && words[0].Option == HelpOption)
        {
            console.Out.Write(HelpText());
            return ExitCodes.Success;
        }

        string file = FileArgument.Parse(Name, words, Syntax, Usage);
        string text = InputText.Read(file, console.In);
        var (shapes, queries) = QueryInput.Read(text);
        console.Out.Write(QueryAnswers.Answer(shapes, queries));
        return ExitCodes.Success;
    }

    private string HelpText() =>
        ($$"""
        Usage: {{Usage}}

        Reads FILE (- for stdin): {"shapes": [SHAPE, ...], "queries": [QUERY, ...]}, coordinates [x, z] in mm.
        SHAPE is one of:

        """ + ShapeGrammar.HelpLines + """
        QUERY is one of (shapes by index, from 0):
          {"type":"distance","a":i,"b":j}
          {"type":"ray","from":[x,z],"to":[x,z]}                   against every shape
          {"type":"cast","shape":i,"translation":[x,z],"against":j}
          {"type":"overlap","aabb":{"min":[x,z],"max":[x,z]}}
        Writes one JSON line per query, in order:
          distance  {"distance":d,"pointA":[x,z],"pointB":[x,z]}   0 and the contact point when they overlap
          ray       {"hit":bool,"shape":i,"point":[x,z],"normal":[x,z],"fraction":f}   the closest hit; null fields on a miss
          cast      {"hit":bool,"fraction":f,"point":[x,z],"normal":[x,z]}   normal from "against" toward the moving shape
          overlap   {"shapes":[i,...]}                              ascending; touching is not overlapping
        A fish adds "partA"/"partB" (distance, cast) or "part" (ray): the leaf involved.
        Bad input: one line "PATH: problem" on stderr (e.g. queries[1].b: must be a shape index 0 … 2, got 5), exit code 2.

        """).ReplaceLineEndings("\n");
}
