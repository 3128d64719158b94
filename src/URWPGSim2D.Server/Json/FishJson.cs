using URWPGSim2D.Collision.Fish;

namespace URWPGSim2D.Server.Json;

/// <summary>
/// The fish SHAPE, <c>{"type":"fish","position":[x,z],"heading":θ,"joints":[φ1,φ2,φ3]}</c> with an
/// optional <c>"size":{"length":L,"width":W,"head":H,"joints":[L1,L2,L3]}</c> (default
/// <see cref="FishSize.Default"/>), turned into a <see cref="FishModel"/>. Fields are checked for
/// presence and length first, then the library validates the values (pose, then size); its
/// parameter names are mapped back to the JSON fields.
/// </summary>
internal static class FishJson
{
    /// <summary>The form of the pose's <c>joints</c> field, for messages.</summary>
    public const string JointAnglesForm = "[φ1, φ2, φ3]";

    /// <summary>The form of the size's <c>joints</c> field, for messages.</summary>
    public const string JointLengthsForm = "[L1, L2, L3]";

    // FishPose constructor parameter → JSON field.
    private static readonly Dictionary<string, string> PoseFields = new()
    {
        ["position"] = "position",
        ["heading"] = "heading",
        ["joint1"] = "joints[0]",
        ["joint2"] = "joints[1]",
        ["joint3"] = "joints[2]",
    };

    // FishSize constructor parameter → JSON field (under the fish object).
    private static readonly Dictionary<string, string> SizeFields = new()
    {
        ["length"] = "size.length",
        ["width"] = "size.width",
        ["head"] = "size.head",
        ["joint1"] = "size.joints[0]",
        ["joint2"] = "size.joints[1]",
        ["joint3"] = "size.joints[2]",
    };

    /// <summary>Builds the fish described by a SHAPE object of type <c>fish</c>.</summary>
    /// <param name="dto">The deserialized SHAPE object.</param>
    /// <param name="fields">The reader of that object (its path names the errors).</param>
    /// <returns>The fish model at the given pose.</returns>
    /// <exception cref="InputException">A field is missing or has the wrong length, or the library rejects a value.</exception>
    public static FishModel Read(ShapeDto dto, FieldReader fields)
    {
        var position = fields.Point(dto.Position, "position");
        float heading = fields.Number(dto.Heading, "heading");
        float[] joints = fields.Numbers(dto.Joints, "joints", 3, JointAnglesForm);
        FishPose pose;
        try
        {
            pose = new FishPose(position, heading, joints[0], joints[1], joints[2]);
        }
        catch (ArgumentException ex)
        {
            throw LibraryArgumentErrors.ToInputError(ex, fields.ObjectPath, PoseFields);
        }

        return new FishModel(ReadSize(dto.Size, fields), pose);
    }

    private static FishSize ReadSize(FishSizeDto? dto, FieldReader fish)
    {
        if (dto is null)
        {
            return FishSize.Default;
        }

        var fields = new FieldReader(fish.PathOf("size"));
        float length = fields.Number(dto.Length, "length");
        float width = fields.Number(dto.Width, "width");
        float head = fields.Number(dto.Head, "head");
        float[] joints = fields.Numbers(dto.Joints, "joints", 3, JointLengthsForm);
        try
        {
            return new FishSize(length, width, head, joints[0], joints[1], joints[2]);
        }
        catch (ArgumentException ex)
        {
            throw LibraryArgumentErrors.ToInputError(ex, fish.ObjectPath, SizeFields);
        }
    }
}
