namespace URWPGSim2D.Common;

/// <summary>A team: its parameters and its fish.</summary>
/// <typeparam name="TFish">The fish type (<see cref="RoboFish"/> for strategies).</typeparam>
[Serializable]
public class Team<TFish>
{
    /// <summary>Creates an empty team on the left half.</summary>
    public Team()
    {
        Para.MyHalfCourt = HalfCourt.LEFT;
    }

    /// <summary>The team's parameters.</summary>
    public TeamCommonPara Para = new();

    /// <summary>The team's fish, in the order of its decisions.</summary>
    public List<TFish> Fishes = new();
}
