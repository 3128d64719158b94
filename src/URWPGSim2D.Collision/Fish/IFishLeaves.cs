namespace URWPGSim2D.Collision.Fish;

/// <summary>
/// The second fish of a fish–fish descent: its three circles, and its leaves (8-DOP slabs and
/// exact polygons) once <see cref="Prepare"/> has been called for their group. A posed
/// <see cref="FishModel"/> (<see cref="ModelLeaves"/>) has them all at once; a model carried into
/// another frame (<see cref="FishInFrame"/>) places only the groups the descent reaches.
/// </summary>
internal interface IFishLeaves
{
    /// <summary>Encloses the whole fish.</summary>
    Circle Root { get; }

    /// <summary>Encloses the body and both pectoral fins (leaves 0 … 2).</summary>
    Circle BodyGroup { get; }

    /// <summary>Encloses the tail (leaves 3 … 7).</summary>
    Circle TailGroup { get; }

    /// <summary>Makes the leaves of group 0 (body) or 1 (tail) available.</summary>
    void Prepare(int group);

    /// <summary>Lower slabs of a prepared leaf's 8-DOP.</summary>
    Vector4 LeafMin(int leaf);

    /// <summary>Upper slabs of a prepared leaf's 8-DOP.</summary>
    Vector4 LeafMax(int leaf);

    /// <summary>A prepared leaf's polygon.</summary>
    ConvexView LeafView(int leaf);
}

/// <summary>A posed model as the second fish of a descent (everything is there already).</summary>
internal readonly struct ModelLeaves(FishModel model) : IFishLeaves
{
    public Circle Root => model.Root;

    public Circle BodyGroup => model.BodyGroup;

    public Circle TailGroup => model.TailGroup;

    public void Prepare(int group)
    {
    }

    public Vector4 LeafMin(int leaf) => model.LeafMin(leaf);

    public Vector4 LeafMax(int leaf) => model.LeafMax(leaf);

    public ConvexView LeafView(int leaf) => model.LeafView(leaf);
}
