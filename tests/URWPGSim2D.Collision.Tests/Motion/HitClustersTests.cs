namespace URWPGSim2D.Collision.Tests.Motion;

/// <summary>
/// The hits of one sample split into clusters that share no moving body: checked against an
/// independent grouping (components of the graph "two hits share a mover", found by a flood fill)
/// over random pairs of few movers, so that chains and ties are common. A cluster's label is its
/// lowest hit, its hits come in hit order, and the clusters come by their earliest estimate, ties
/// by the lower label.
/// </summary>
public sealed class HitClustersTests
{
    // (hits, movers): a single hit, a few hits on few movers (long chains), many hits.
    private static readonly (int Count, int Movers)[] Cases = [(1, 3), (5, 4), (12, 6), (40, 30), (200, 150)];

    [Fact]
    public void ClustersAreTheComponentsInTimeOrder()
    {
        foreach ((int count, int movers) in Cases)
        {
            Check(count, movers);
        }
    }

    private static void Check(int count, int movers)
    {
        var random = new Random((count * 31) + movers);
        var clusters = new HitClusters();
        for (int trial = 0; trial < 40; trial++)
        {
            var table = new PairTable(movers);
            int[] slots = new int[count];
            int[] moverA = new int[count], moverB = new int[count];
            for (int i = 0; i < count; i++)
            {
                moverA[i] = random.Next(movers);
                moverB[i] = random.Next(3) == 0 ? -1 : random.Next(movers);
                if (moverB[i] == moverA[i])
                {
                    moverB[i] = -1;
                }

                slots[i] = table.Add(new PlannedPair(moverA[i], 1000 + i, moverA[i], moverB[i], 1f), 1f, 1.0, 0.0);
            }

            clusters.Load(slots, new Hit[count], count, table);
            double[] estimate = new double[count];
            for (int i = 0; i < count; i++)
            {
                // Few distinct times, so clusters often tie.
                estimate[i] = random.Next(4) / 4.0;
                clusters.Estimate[i] = estimate[i];
            }

            clusters.Cluster();

            int[] component = Components(moverA, moverB);
            int[] expectedOrder = Enumerable.Range(0, count).Where(i => component[i] == i)
                .OrderBy(root => Enumerable.Range(0, count).Where(k => component[k] == root).Min(k => estimate[k]))
                .ThenBy(root => root)
                .ToArray();
            Assert.Equal(expectedOrder, clusters.ClustersByTime().ToArray());
            foreach (int root in expectedOrder)
            {
                var members = new List<int>();
                for (int i = clusters.FirstOf(root); i >= 0; i = clusters.NextOf(i))
                {
                    members.Add(i);
                    Assert.Equal(root, clusters.Label[i]);
                }

                Assert.Equal(Enumerable.Range(0, count).Where(k => component[k] == root), members);
            }
        }
    }

    // Each hit's component, named by its lowest hit: a flood fill over hits sharing a mover.
    private static int[] Components(int[] moverA, int[] moverB)
    {
        int n = moverA.Length;
        int[] component = Enumerable.Repeat(-1, n).ToArray();
        for (int start = 0; start < n; start++)
        {
            if (component[start] >= 0)
            {
                continue;
            }

            var stack = new Stack<int>([start]);
            component[start] = start;
            while (stack.Count > 0)
            {
                int h = stack.Pop();
                for (int k = 0; k < n; k++)
                {
                    if (component[k] < 0 && Shares(h, k))
                    {
                        component[k] = start;
                        stack.Push(k);
                    }
                }
            }
        }

        return component;

        bool Shares(int h, int k) =>
            moverA[h] == moverA[k] || moverA[h] == moverB[k] || (moverB[h] >= 0 && (moverB[h] == moverA[k] || moverB[h] == moverB[k]));
    }
}
