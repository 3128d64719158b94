namespace URWPGSim2D.Server.Cli;

/// <summary>
/// <c>query FILE</c>: reads <c>{"shapes": [SHAPE…], "queries": [QUERY…]}</c> and writes one JSON
/// line per query (<see cref="QueryAnswers"/>). The whole input is validated before anything is
/// computed or written: on bad input stdout stays empty.
/// </summary>
internal sealed class QueryCommand : JsonFileCommand
{
    /// <summary>Declares the command.</summary>
    public QueryCommand()
        : base("query", "Distances, ray casts, shape casts and box overlaps over shapes from a JSON file.", "shapes and queries (JSON), - for stdin")
    {
    }

    /// <inheritdoc />
    protected override string Answer(string text)
    {
        var (shapes, queries) = QueryInput.Read(text);
        return QueryAnswers.Answer(shapes, queries);
    }

    /// <inheritdoc />
    protected override string HelpText() =>
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
