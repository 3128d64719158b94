using System.Collections;
using System.Reflection;
using URWPGSim2D.Collision.BroadPhase;

namespace URWPGSim2D.Server.Tests.Scenario;

/// <summary>
/// The Box2D side-by-side harness (<c>../shared/peers/box2d/cs</c>, run by <c>benchmarks/box2d.sh</c>,
/// which points its copy at these names) builds the crowd scene and its match by reflection, by these
/// names and argument lists. Renaming or overloading them breaks the harness only at run time, so the
/// lookups it makes are made here.
/// </summary>
public sealed class PeerHarnessContractTests
{
    private const BindingFlags Static = BindingFlags.Public | BindingFlags.NonPublic | BindingFlags.Static;
    private const BindingFlags Instance = BindingFlags.Public | BindingFlags.NonPublic | BindingFlags.Instance;
    private static readonly Assembly Hosting = Assembly.Load("URWPGSim2D.Hosting");
    private static readonly Assembly Engine = Assembly.Load("URWPGSim2D.Engine");

    [Fact]
    public void TheHarnessBuildsAndStepsACrowdMatchByReflection()
    {
        object scenario = Engine.GetType("URWPGSim2D.Engine.Scenario.CrowdScenario", true)!
            .GetMethod("Create", Static)!
            .Invoke(null, [100, 1UL, 3000])!;
        var build = Hosting.GetType("URWPGSim2D.Hosting.MatchBuilder", true)!.GetMethod("Build", Static)!;
        object match = build.Invoke(null, [scenario, null, null, null, 100, BroadPhaseKind.UniformGrid, null])!;
        var step = (Action)Delegate.CreateDelegate(typeof(Action), match, match.GetType().GetMethod("Step")!);
        step();
        Assert.Equal(1, ((URWPGSim2D.Engine.Matches.Match)match).World.Cycle);
    }

    [Fact]
    public void TheHarnessReadsTheCrowdScenesBodiesByReflection()
    {
        object scenario = CrowdScenario.Create(100, 1UL, 3000);
        Assert.True((float)Get(scenario, "FieldLength") > 0f);
        Assert.True((float)Get(scenario, "FieldWidth") > 0f);
        _ = (bool)Get(scenario, "GoalBlocks");
        foreach (object f in (IEnumerable)Get(scenario, "Fish"))
        {
            _ = (Vector2)Get(f, "Position");
            _ = (float)Get(f, "Heading");
            object d = Get(f, "Decision");
            Assert.True(Table("URWPGSim2D.Engine.Simulation.Kinematics.SpeedTable", "TargetSpeed", (int)Get(d, "VCode")) >= 0f);
            _ = Table("URWPGSim2D.Engine.Simulation.Kinematics.TurnTable", "TargetTurnRate", (int)Get(d, "TCode"));
        }

        foreach (object b in (IEnumerable)Get(scenario, "Balls"))
        {
            _ = (Vector2)Get(b, "Position");
            _ = (Vector2)Get(b, "Velocity");
            Assert.True((float)Get(b, "Radius") > 0f);
        }

        foreach (object o in (IEnumerable)Get(scenario, "Obstacles"))
        {
            _ = (Vector2)Get(o, "Center");
            string kind = Get(o, "Kind").ToString()!;
            _ = kind == "Round" ? (float)Get(o, "Radius") : (float)Get(o, "Length") + (float)Get(o, "Width") + (float)Get(o, "Heading");
        }
    }

    private static object Get(object o, string name) =>
        o.GetType().GetProperty(name, Instance)!.GetValue(o)!;

    private static float Table(string type, string method, int code) =>
        (float)Engine.GetType(type, true)!.GetMethod(method, Static)!.Invoke(null, [code])!;
}
