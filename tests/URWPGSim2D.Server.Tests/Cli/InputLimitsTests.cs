namespace URWPGSim2D.Server.Tests.Cli;

/// <summary>Each command's input limits (docs/cli.md, "Limits"): one element over is refused up front, exactly the limit is read.</summary>
public sealed class InputLimitsTests
{
    private const string Circle = "{\"type\":\"circle\",\"center\":[0,0],\"radius\":1}";
    private const string Pair = "{\"a\":" + Circle + ",\"b\":" + Circle + "}";

    [Fact]
    public void ShapesReadsItsLimitAndRefusesOneMore()
    {
        Assert.Equal(0, CliRun.Of(Array(Circle, InputLimits.Shapes), "shapes", "-").ExitCode);
        CollideErrorTests.AssertOneLineFailure(
            CliRun.Of(Array(Circle, InputLimits.Shapes + 1), "shapes", "-"),
            "shapes: more than 100000 elements, the limit of shapes (docs/cli.md, Limits)");
    }

    [Fact]
    public void CollideRefusesOnePairOverItsLimit()
    {
        CollideErrorTests.AssertOneLineFailure(
            CliRun.Of(Array(Pair, InputLimits.Pairs + 1), "collide", "-"),
            "pairs: more than 200000 elements, the limit of collide (docs/cli.md, Limits)");
    }

    [Fact]
    public void RenderRefusesOneElementOverItsLimitOfEitherKind()
    {
        CollideErrorTests.AssertOneLineFailure(
            CliRun.Of(Array(Circle, 10_001), "render", "-", "--svg", "-"),
            "shapes: more than 10000 elements, the limit of render (docs/cli.md, Limits)");
        CollideErrorTests.AssertOneLineFailure(
            CliRun.Of(Array(Pair, 10_001), "render", "-", "--svg", "-"),
            "pairs: more than 10000 elements, the limit of render (docs/cli.md, Limits)");
        Assert.Equal(0, CliRun.Of(Array(Circle, 10_000), "render", "-", "--svg", "-").ExitCode);
    }

    [Fact]
    public void AScenarioOfMoreBodiesThanTheLimitIsRefusedBeforeItIsBuilt()
    {
        string obstacles = Array("{\"type\":\"round\",\"center\":[0,0],\"radius\":1}", 10_000);
        string balls = Array("{\"position\":[0,0],\"radius\":1}", 10_001);

        CollideErrorTests.AssertOneLineFailure(
            CliRun.Of($"{{\"fish\":[],\"balls\":{balls},\"obstacles\":{obstacles}}}", "run", "--scenario", "-"),
            "20001 bodies (fish, balls and obstacles), more than the limit of 20000 (docs/cli.md, Limits)");
    }

    [Fact]
    public void AnInputFileOverTheSizeLimitIsRefusedWithoutBeingRead()
    {
        string file = Path.GetTempFileName();
        try
        {
            using (var stream = File.OpenWrite(file))
            {
                stream.SetLength(InputLimits.InputBytes + 1); // sparse: nothing to read
            }

            foreach (string command in new[] { "collide", "shapes" })
            {
                CollideErrorTests.AssertOneLineFailure(
                    CliRun.Of(string.Empty, command, file),
                    $"{file}: the input is 67108865 bytes, more than the limit of 64 MiB (docs/cli.md, Limits)");
            }

            CollideErrorTests.AssertOneLineFailure(
                CliRun.Of(string.Empty, "run", "--scenario", file),
                $"{file}: the input is 67108865 bytes, more than the limit of 64 MiB (docs/cli.md, Limits)");
        }
        finally
        {
            File.Delete(file);
        }
    }

    private static string Array(string element, int count) =>
        new StringBuilder(2 + count * (element.Length + 1)).Append('[').AppendJoin(',', Enumerable.Repeat(element, count)).Append(']').ToString();
}
