// Every public type of the strategy SDK, forwarded from its former assembly name: a strategy
// compiled against URWPGSim2D.Strategy finds each of them in URWPGSim2D.Strategies.
// TypeForwardsTests checks that the list holds every public type of the SDK.
using System.Runtime.CompilerServices;
using URWPGSim2D.Strategies;

[assembly: TypeForwardedTo(typeof(BallView))]
[assembly: TypeForwardedTo(typeof(DebugDraw))]
[assembly: TypeForwardedTo(typeof(DebugRecorder))]
[assembly: TypeForwardedTo(typeof(DebugShape))]
[assembly: TypeForwardedTo(typeof(DebugShapeJson))]
[assembly: TypeForwardedTo(typeof(DebugShapeKind))]
[assembly: TypeForwardedTo(typeof(Decision))]
[assembly: TypeForwardedTo(typeof(FieldSensor))]
[assembly: TypeForwardedTo(typeof(FishView))]
[assembly: TypeForwardedTo(typeof(IStrategy))]
[assembly: TypeForwardedTo(typeof(MatchSnapshot))]
[assembly: TypeForwardedTo(typeof(MatchSnapshotWriter))]
[assembly: TypeForwardedTo(typeof(ObstacleKind))]
[assembly: TypeForwardedTo(typeof(ObstacleView))]
[assembly: TypeForwardedTo(typeof(OrderedVariables))]
[assembly: TypeForwardedTo(typeof(SensedBody))]
[assembly: TypeForwardedTo(typeof(SensedDistance))]
[assembly: TypeForwardedTo(typeof(SensedHit))]
[assembly: TypeForwardedTo(typeof(SensedKind))]
[assembly: TypeForwardedTo(typeof(SensedKinds))]
[assembly: TypeForwardedTo(typeof(StrategyContractException))]
