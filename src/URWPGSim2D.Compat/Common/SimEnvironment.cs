using System.Collections;

namespace URWPGSim2D.Common;

/// <summary>The environment of an item: the field, balls, obstacles and channels.</summary>
[Serializable]
public class SimEnvironment : ICloneable
{
    /// <summary>The field (the process-wide <see cref="Field.Instance"/>, as in the original).</summary>
    public Field FieldInfo = Field.Instance();

    /// <summary>The balls, by index.</summary>
    public List<Ball> Balls = new();

    /// <summary>The round obstacles.</summary>
    public List<RoundedObstacle> ObstaclesRound = new();

    /// <summary>The rectangular obstacles.</summary>
    public List<RectangularObstacle> ObstaclesRect = new();

    /// <summary>Moving rectangular obstacles (none in the items here).</summary>
    public List<RectangularDynamic> DynamicRect = new();

    /// <summary>Channels (none in the items here).</summary>
    public List<Channel> Channels = new();

    /// <summary>Environment values an item passes to strategies (string keys and values).</summary>
    public Hashtable HtEnvVariables = new();

    /// <summary>A deep copy (the field stays the shared instance).</summary>
    /// <returns>A new <see cref="SimEnvironment"/>.</returns>
    public virtual object Clone()
    {
        var copy = new SimEnvironment { FieldInfo = FieldInfo, HtEnvVariables = (Hashtable)HtEnvVariables.Clone() };
        foreach (var b in Balls)
        {
            copy.Balls.Add((Ball)b.Clone());
        }

        foreach (var o in ObstaclesRound)
        {
            copy.ObstaclesRound.Add((RoundedObstacle)o.Clone());
        }

        foreach (var o in ObstaclesRect)
        {
            copy.ObstaclesRect.Add((RectangularObstacle)o.Clone());
        }

        foreach (var o in DynamicRect)
        {
            copy.DynamicRect.Add((RectangularDynamic)o.Clone());
        }

        foreach (var c in Channels)
        {
            copy.Channels.Add((Channel)c.Clone());
        }

        return copy;
    }
}
