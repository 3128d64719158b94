using System.Text.Json;

namespace URWPGSim2D.Server.Cli;

/// <summary>
/// <c>shapes FILE</c>: reads a JSON array of SHAPEs and writes, in the same order, one compact
/// JSON array of their exact collision pieces in world coordinates (<see cref="ShapePiecesDto"/>):
/// a fish's eight leaf polygons and tree circles, another shape's polygon or circle and outer
/// circle. Every SHAPE is validated before anything is written.
/// </summary>
internal sealed class ShapesCommand : JsonFileCommand
{
    /// <summary>Declares the command.</summary>
    public ShapesCommand()
        : base("shapes", "Write the exact collision pieces (polygons, circles, fish leaves and tree) of shapes as JSON.", "shapes (JSON), - for stdin")
    {
    }

    /// <inheritdoc />
    protected override string Answer(string text)
    {
        var pieces = Array.ConvertAll(ShapesInput.Read(text), ShapePiecesDto.From);
        return JsonSerializer.Serialize(pieces, OutputJsonContext.Default.ShapePiecesDtoArray) + "\n";
    }

    /// <inheritdoc />
    protected override string HelpText() =>
        ($$"""
        Usage: {{Usage}}

        Reads FILE (- for stdin): a JSON array of SHAPEs, coordinates [x, z] in mm. SHAPE is one of:

        """ + ShapeGrammar.HelpLines + """
        Writes to stdout one line: a JSON array with, for each SHAPE in input order, its exact collision
        pieces in world coordinates (vertices counter-clockwise in (x, z), i.e. clockwise on a +Z-down screen):
          {"type":"circle","center":[x,z],"radius":r,"outer":CIRCLE}
          {"type":"aabb","min":[x,z],"max":[x,z],"vertices":[4 corners],"outer":CIRCLE}
          {"type":"kdop8","min":[4 slabs],"max":[4 slabs],"vertices":[1 to 8],"outer":CIRCLE}   slabs tightened
          {"type":"polygon","vertices":[[x,z],...],"outer":CIRCLE}
          {"type":"segment","a":[x,z],"b":[x,z],"vertices":[a,b],"outer":CIRCLE}
          {"type":"fish","leaves":{"leftPectoral":[[x,z],...],"body":...,"rightPectoral":...,"tail1":...,
            "tail2":...,"tail3":...,"leftCaudal":...,"rightCaudal":...},"bounds":{"root":CIRCLE,"body":CIRCLE,"tail":CIRCLE}}
        where CIRCLE is {"center":[x,z],"radius":r}.
        Bad input: one line "PATH: problem" on stderr (e.g. shapes[3].joints: must be an array of 3 numbers
        [φ1, φ2, φ3], got 2), exit code 2.

        """).ReplaceLineEndings("\n");
}
