using System.Collections.Generic;
using URWPGSim2D.Collision.Fish;

namespace URWPGSim2D.Server.Simulation;

/// <summary>
/// Scratch models that lay out a pair's fish leaves at their poses now (the separation's summed
/// push direction): two for each fish size of the world — one per fish of a pair — built with the
/// world, since a fish's size never changes, so no contact builds one mid-match. The motion world
/// keeps its own models where its stepping needs them; these are posed again at every use.
/// </summary>
internal sealed class ScratchFishModels
{
    private readonly FishState[] _fish;
    private readonly FishModel[] _models;
    private readonly int[] _sizeOf;

    /// <summary>Builds the models for the sizes of the world's <paramref name="fish"/>.</summary>
    public ScratchFishModels(FishState[] fish)
    {
        _fish = fish;
        _sizeOf = new int[fish.Length];
        var sizes = new Dictionary<FishSize, int>();
        var models = new List<FishModel>();
        for (int i = 0; i < fish.Length; i++)
        {
            FishSize size = fish[i].Size;
            if (!sizes.TryGetValue(size, out int known))
            {
                known = sizes.Count;
                sizes.Add(size, known);
                models.Add(new FishModel(size, fish[i].Pose));
                models.Add(new FishModel(size, fish[i].Pose));
            }

            _sizeOf[i] = known;
        }

        _models = models.ToArray();
    }

    /// <summary>Model <paramref name="slot"/> (0 or 1: the first or second fish of a pair) of the size of fish <paramref name="fish"/>, laid out at that fish's pose and joints now.</summary>
    public FishModel Posed(int slot, int fish)
    {
        FishModel model = _models[(2 * _sizeOf[fish]) + slot];
        model.SetPose(_fish[fish].Pose);
        return model;
    }
}
