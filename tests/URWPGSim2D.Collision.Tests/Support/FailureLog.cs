using System.Text;

namespace URWPGSim2D.Collision.Tests.Support;

/// <summary>
/// Collects the failures of a property test over many random cases and fails once at the end,
/// reporting how many cases failed and the first few in full (reproducible descriptions).
/// </summary>
public sealed class FailureLog
{
    private const int Shown = 5;
    private readonly List<string> _first = [];

    /// <summary>Number of cases checked.</summary>
    public int Checked { get; private set; }

    /// <summary>Number of cases that failed.</summary>
    public int Failed { get; private set; }

    /// <summary>Counts one case.</summary>
    public void Case() => Checked++;

    /// <summary>Records a failure when <paramref name="ok"/> is false.</summary>
    public void Check(bool ok, string description)
    {
        if (ok)
        {
            return;
        }

        Failed++;
        if (_first.Count < Shown)
        {
            _first.Add(description);
        }
    }

    /// <summary>Fails the test if any case failed; also fails if fewer than <paramref name="minimumChecked"/> cases were checked (a test that checks nothing cannot fail).</summary>
    public void AssertNone(int minimumChecked)
    {
        Assert.True(Checked >= minimumChecked, $"only {Checked} cases were checked, expected at least {minimumChecked}");
        if (Failed == 0)
        {
            return;
        }

        var text = new StringBuilder($"{Failed} of {Checked} cases failed; first {_first.Count}:");
        foreach (var f in _first)
        {
            text.AppendLine().Append("  - ").Append(f);
        }

        Assert.Fail(text.ToString());
    }
}
