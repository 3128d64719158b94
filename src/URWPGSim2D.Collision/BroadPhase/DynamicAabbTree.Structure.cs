namespace URWPGSim2D.Collision.BroadPhase;

/// <content>Inserting and removing leaves, refitting and rebalancing the path to the root.</content>
internal sealed partial class DynamicAabbTree
{
    // Descends toward the sibling whose union with the leaf adds the least perimeter to the tree
    // (a node's own cost: 2·perimeter(node ∪ leaf); pushing the leaf further down costs at least the
    // growth of this node, 2·(perimeter(node ∪ leaf) − perimeter(node))), then splices a new parent.
    private void InsertLeaf(int leaf)
    {
        if (_root == Null)
        {
            _root = leaf;
            _nodes[leaf].Parent = Null;
            return;
        }

        Vector2 lo = _nodes[leaf].Min, hi = _nodes[leaf].Max;
        int index = _root;
        while (!_nodes[index].IsLeaf)
        {
            ref Node node = ref _nodes[index];
            float area = Perimeter(node.Min, node.Max);
            float combined = Perimeter(Vector2.Min(node.Min, lo), Vector2.Max(node.Max, hi));
            float here = 2f * combined;
            float inherited = 2f * (combined - area);
            float cost1 = DescentCost(node.Child1, lo, hi) + inherited;
            float cost2 = DescentCost(node.Child2, lo, hi) + inherited;
            if (here < cost1 && here < cost2)
            {
                break;
            }

            index = cost1 <= cost2 ? node.Child1 : node.Child2;
        }

        int sibling = index;
        int oldParent = _nodes[sibling].Parent;
        int parent = Allocate();
        ref Node p = ref _nodes[parent];
        p.Parent = oldParent;
        p.Min = Vector2.Min(_nodes[sibling].Min, lo);
        p.Max = Vector2.Max(_nodes[sibling].Max, hi);
        p.Height = _nodes[sibling].Height + 1;
        p.Proxy = -1;
        p.Child1 = sibling;
        p.Child2 = leaf;
        ReplaceChild(oldParent, sibling, parent);
        _nodes[sibling].Parent = parent;
        _nodes[leaf].Parent = parent;
        RefitUpward(parent);
    }

    private float DescentCost(int child, Vector2 lo, Vector2 hi)
    {
        ref Node c = ref _nodes[child];
        float grown = Perimeter(Vector2.Min(c.Min, lo), Vector2.Max(c.Max, hi));
        return c.IsLeaf ? grown : grown - Perimeter(c.Min, c.Max);
    }

    private void RemoveLeaf(int leaf)
    {
        if (leaf == _root)
        {
            _root = Null;
            return;
        }

        int parent = _nodes[leaf].Parent;
        int grand = _nodes[parent].Parent;
        int sibling = _nodes[parent].Child1 == leaf ? _nodes[parent].Child2 : _nodes[parent].Child1;
        ReplaceChild(grand, parent, sibling);
        _nodes[sibling].Parent = grand;
        Release(parent);
        if (grand != Null)
        {
            RefitUpward(grand);
        }
    }

    // Points `parent`'s link to `oldChild` at `newChild` (or the root, when parent is Null).
    private void ReplaceChild(int parent, int oldChild, int newChild)
    {
        if (parent == Null)
        {
            _root = newChild;
        }
        else if (_nodes[parent].Child1 == oldChild)
        {
            _nodes[parent].Child1 = newChild;
        }
        else
        {
            _nodes[parent].Child2 = newChild;
        }
    }

    private void RefitUpward(int index)
    {
        while (index != Null)
        {
            index = Balance(index);
            ref Node node = ref _nodes[index];
            Fit(ref node);
            index = node.Parent;
        }
    }

    private void Fit(ref Node node)
    {
        ref Node c1 = ref _nodes[node.Child1];
        ref Node c2 = ref _nodes[node.Child2];
        node.Height = 1 + Math.Max(c1.Height, c2.Height);
        node.Min = Vector2.Min(c1.Min, c2.Min);
        node.Max = Vector2.Max(c1.Max, c2.Max);
    }

    // AVL rotation: when one child of `a` is more than one level taller than the other, the taller
    // child takes a's place and a adopts the shorter of that child's two children. Returns the node
    // now at a's place.
    private int Balance(int a)
    {
        if (_nodes[a].IsLeaf || _nodes[a].Height < 2)
        {
            return a;
        }

        int b = _nodes[a].Child1;
        int c = _nodes[a].Child2;
        int balance = _nodes[c].Height - _nodes[b].Height;
        if (balance > 1)
        {
            RotateUp(a, c, keepIsChild1: true);
            return c;
        }

        if (balance < -1)
        {
            RotateUp(a, b, keepIsChild1: false);
            return b;
        }

        return a;
    }

    // `up` (a child of a) replaces a. Of up's two children the taller stays with up, the shorter
    // moves to a in up's old slot. keepIsChild1: whether a keeps its Child1 (up was Child2).
    private void RotateUp(int a, int up, bool keepIsChild1)
    {
        int f = _nodes[up].Child1;
        int g = _nodes[up].Child2;
        _nodes[up].Child1 = a;
        _nodes[up].Parent = _nodes[a].Parent;
        _nodes[a].Parent = up;
        ReplaceChild(_nodes[up].Parent, a, up);

        int taller = _nodes[f].Height > _nodes[g].Height ? f : g;
        int shorter = taller == f ? g : f;
        _nodes[up].Child2 = taller;
        if (keepIsChild1)
        {
            _nodes[a].Child2 = shorter;
        }
        else
        {
            _nodes[a].Child1 = shorter;
        }

        _nodes[shorter].Parent = a;
        Fit(ref _nodes[a]);
        Fit(ref _nodes[up]);
    }
}
