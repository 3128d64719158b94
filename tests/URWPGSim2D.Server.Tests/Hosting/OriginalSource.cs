namespace URWPGSim2D.Server.Tests.Hosting;

/// <summary>
/// Writes a strategy source in the original's API (the class <c>URWPGSim2D.Strategy.Strategy</c>,
/// <c>GetDecision(Mission, int)</c>), as teams wrote them, with a given body and members, for the
/// hostile-strategy tests. The body runs after the fish's decisions are filled with (10, 7); it
/// may read <c>cycle</c> (0 on the first call) and <c>mission</c>.
/// </summary>
internal static class OriginalSource
{
    /// <summary>The usings every source gets.</summary>
    public const string Usings = "using System; using System.IO; using System.Collections.Generic; using System.Runtime.InteropServices; using URWPGSim2D.Common; using URWPGSim2D.StrategyLoader;\n";

    /// <summary>Writes <c>FOLDER/NAME.cs</c> and returns its path.</summary>
    public static string Write(string folder, string name, string body, string members = "")
    {
        string file = Path.Combine(folder, name + ".cs");
        File.WriteAllText(file, Usings + $$"""
            namespace URWPGSim2D.Strategy
            {
                public class Strategy : MarshalByRefObject, IStrategy
                {
                    public override object InitializeLifetimeService() { return null; }
                    private int cycle = -1;
                    {{members}}
                    public string GetTeamName() { return "{{name}}"; }
                    public Decision[] GetDecision(Mission mission, int teamId)
                    {
                        cycle++;
                        Decision[] d = new Decision[mission.CommonPara.FishCntPerTeam];
                        for (int i = 0; i < d.Length; i++) { d[i].VCode = 10; d[i].TCode = 7; }
                        {{body}}
                        return d;
                    }
                }
            }
            """);
        return file;
    }
}
