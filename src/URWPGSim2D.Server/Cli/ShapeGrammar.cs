namespace URWPGSim2D.Server.Cli;

/// <summary>The SHAPE grammar as shown in the <c>--help</c> of <c>collide</c>, <c>shapes</c> and <c>render</c> (docs/cli.md has the rules).</summary>
internal static class ShapeGrammar
{
    /// <summary>One SHAPE form per line, each indented by two spaces, ending in a newline.</summary>
    public const string HelpLines =
        """
          {"type":"circle","center":[x,z],"radius":r}
          {"type":"aabb","min":[x,z],"max":[x,z]}
          {"type":"kdop8","min":[s0,s1,s2,s3],"max":[s0,s1,s2,s3]}   slabs along (1,0), (0,1), (√½,√½), (√½,−√½)
          {"type":"polygon","vertices":[[x,z],...]}                  convex, either winding, 3 to 64 vertices
          {"type":"segment","a":[x,z],"b":[x,z]}
          {"type":"fish","position":[x,z],"heading":θ,"joints":[φ1,φ2,φ3]}   angles in rad; optional
              "size":{"length":L,"width":W,"head":H,"joints":[L1,L2,L3]} (default 160, 45, 30, [88, 66, 55])

        """;
}
