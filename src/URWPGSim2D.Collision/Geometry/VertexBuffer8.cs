namespace URWPGSim2D.Collision.Geometry;

/// <summary>Eight plane vectors stored inline (no heap): the vertices or edge normals of an 8-DOP or a small polygon.</summary>
[InlineArray(8)]
internal struct VertexBuffer8
{
    private Vector2 _element;
}
