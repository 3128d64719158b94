using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;

namespace URWPGSim2D.Tests.OldStrategies;

/// <summary>
/// Real strategy DLLs compiled by Visual Studio for the original simulator (.NET 2.0, x86, strong-named
/// references to the original's assemblies and XNA 3.1), read where the project's shared data keeps them:
/// <c>../shared/olddll</c> beside the repository. They are test data, never copied into the repository.
/// </summary>
internal static class RealOldDlls
{
    /// <summary>The folder of the real DLLs; the tests that use it fail (not skip) when it is missing.</summary>
    public static string Folder { get; } = Find();

    /// <summary>
    /// What is known of each DLL from its own IL (read with a disassembler, not from this project's code):
    /// the name its <c>GetTeamName</c> returns and the item it was written for. The folder's README names
    /// the item by the file name's prefix; the one exception is noted.
    /// </summary>
    public static IReadOnlyList<RealOldDll> Known { get; } =
    [
        // GetDecision returns its decision array untouched: every fish gets speed 0, turn 0 (the original's template).
        new("ball-grab-StrategyNew2V2.dll", "ball-grab", "抢球博弈 Test Team", Idle: true),

        // Steers fish 0 to fixed points while RemainingCycles / 10 is in (570, 600): the first 30 s of a ten-minute match.
        new("ball-grab-StrategyRainbow2V2.dll", "ball-grab", "彩虹大抢球 Test Team", Idle: false),

        // Filed under double-fish-race-via-holes, but its code is for 协作过孔 (push-ball-via-channel): it reads that
        // item's mission variables (IsCollidedBallAndFish{0,1}AtStage{1,2,4}), two fish of its own team and ball 0;
        // the double-fish race has one fish a team and no ball.
        new("double-fish-race-via-holes-StrategySpeedRaceTwoFishesPassHole.dll", "push-ball-via-channel", "中国人民解放军理工大学", Idle: false),

        new("polo-5v5-Strategy5VS5.dll", "polo-5v5", "5V5", Idle: false),
    ];

    /// <summary>Every DLL in the folder: the known ones, and any other with its item read from the file name's prefix.</summary>
    public static IReadOnlyList<RealOldDll> All()
    {
        var all = new List<RealOldDll>(Known);
        foreach (string file in Directory.GetFiles(Folder, "*.dll").Select(f => Path.GetFileName(f)).Order(StringComparer.Ordinal))
        {
            if (!all.Exists(d => d.File == file))
            {
                int dash = file.IndexOf("-Strategy", StringComparison.Ordinal);
                all.Add(new RealOldDll(file, dash > 0 ? file[..dash] : "ball-grab", TeamName: null, Idle: false));
            }
        }

        return all;
    }

    /// <summary>The full path of a DLL of the folder.</summary>
    public static string PathOf(string file) => Path.Combine(Folder, file);

    private static string Find()
    {
        for (var dir = new DirectoryInfo(AppContext.BaseDirectory); dir is not null; dir = dir.Parent)
        {
            if (File.Exists(Path.Combine(dir.FullName, "URWPGSim2D.Collision.sln")))
            {
                string folder = Path.GetFullPath(Path.Combine(dir.FullName, "..", "shared", "olddll"));
                return Directory.Exists(folder)
                    ? folder
                    : throw new InvalidOperationException($"the real old DLLs are not at {folder} (../shared/olddll beside the repository)");
            }
        }

        throw new InvalidOperationException("the repository root (URWPGSim2D.Collision.sln) is not above " + AppContext.BaseDirectory);
    }
}

/// <summary>One real DLL built for the original.</summary>
/// <param name="File">Its file name in <see cref="RealOldDlls.Folder"/>.</param>
/// <param name="Item">The item it was written for (its slug).</param>
/// <param name="TeamName">What its <c>GetTeamName</c> returns, where known.</param>
/// <param name="Idle">Whether every decision it returns is all zero (speed code 0, turn code 0).</param>
internal sealed record RealOldDll(string File, string Item, string? TeamName, bool Idle)
{
    /// <inheritdoc/>
    public override string ToString() => File;
}
