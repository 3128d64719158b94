namespace URWPGSim2D.Common;

/// <summary>The half of the field a team defends.</summary>
public enum HalfCourt
{
    /// <summary>The left half (x &lt; 0); the team attacks the right goal.</summary>
    LEFT = 0,

    /// <summary>The right half (x &gt; 0); the team attacks the left goal.</summary>
    RIGHT,
}
